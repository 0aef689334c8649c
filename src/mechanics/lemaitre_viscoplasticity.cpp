#include "mechanics/lemaitre_viscoplasticity.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "core/number_format.hpp"
#include "mechanics/plane_tensor.hpp"

namespace aster::mechanics {
namespace {

LemaitreParameters checkedParameters(const char* relation, double young, double poisson, double n, double inverseK,
                                     double inverseM, double theta) {
  const std::string law = relation;
  if (!(n > 0)) throw Error(law + ": LEMAITRE's N = " + format::shortest(n) + " must be > 0");
  if (!(inverseK >= 0)) throw Error(law + ": LEMAITRE's UN_SUR_K = " + format::shortest(inverseK) + " must be >= 0");
  if (!(inverseM >= 0)) throw Error(law + ": LEMAITRE's UN_SUR_M = " + format::shortest(inverseM) + " must be >= 0");
  // code_aster integrates these laws by the theta scheme with theta = 1 or 0.5 only.
  if (theta != 1.0 && theta != 0.5)
    throw Error(law + ": PARM_THETA = " + format::shortest(theta) +
                " is not available; the theta scheme of this relation takes PARM_THETA = 1 (implicit) or 0.5 "
                "(semi-implicit)");
  LemaitreParameters p;
  p.young = young;
  p.poisson = poisson;
  p.exponent = n;
  p.inverseK = inverseK;
  p.inverseM = inverseM;
  p.theta = theta;
  return p;
}

}  // namespace

LemaitreParameters lemaitreParameters(double young, double poisson, double n, double inverseK, double inverseM,
                                      double theta) {
  return checkedParameters("LEMAITRE", young, poisson, n, inverseK, inverseM, theta);
}

LemaitreParameters nortonParameters(double young, double poisson, double n, double inverseK, double inverseM,
                                    double theta) {
  if (inverseM != 0)
    throw Error("NORTON: LEMAITRE's UN_SUR_M = " + format::shortest(inverseM) +
                " must be 0 (Norton's law has no strain hardening; RELATION='LEMAITRE' has it)");
  LemaitreParameters p = checkedParameters("NORTON", young, poisson, n, inverseK, inverseM, theta);
  p.variables = LemaitreVariables::Norton;
  return p;
}

LemaitreViscoplasticity::LemaitreViscoplasticity(LemaitreParameters parameters, PlaneHypothesis hypothesis)
    : parameters_(std::move(parameters)), hypothesis_(hypothesis) {
  const double E = parameters_.young, nu = parameters_.poisson;
  const char* law = parameters_.variables == LemaitreVariables::Norton ? "NORTON" : "LEMAITRE";
  if (!(E > 0)) throw Error(std::string(law) + ": Young's modulus E must be > 0, got " + format::shortest(E));
  if (!(nu > -1 && nu < 0.5))
    throw Error(std::string(law) + ": Poisson's ratio NU must be in (-1, 0.5), got " + format::shortest(nu));
  if (parameters_.maxIterations < 1) throw Error(std::string(law) + ": ITER_INTE_MAXI must be >= 1");
  if (hypothesis == PlaneHypothesis::PlaneStress)
    throw Error(std::string(law) + " is not available in C_PLAN (code_aster has it in 3D, D_PLAN and AXIS)");
  mu_ = E / (2 * (1 + nu));
  bulk_ = E / (3 * (1 - 2 * nu));
}

int LemaitreViscoplasticity::internalVariableCount() const {
  return parameters_.variables == LemaitreVariables::Lemaitre ? 2 : 7;
}

std::vector<std::string> LemaitreViscoplasticity::internalVariableNames() const {
  if (parameters_.variables == LemaitreVariables::Lemaitre) return {"EPSPEQ", "VIDE"};
  return {"EPSPXX", "EPSPYY", "EPSPZZ", "EPSPXY", "EPSPXZ", "EPSPYZ", "VIDE"};
}

void LemaitreViscoplasticity::rate(double x, double p, double& g, double& dgdx, double& dgdp) const {
  const double n = parameters_.exponent, invM = parameters_.inverseM;
  g = dgdx = dgdp = 0;
  if (x <= 0) return;
  if (invM == 0) {
    g = std::pow(x * parameters_.inverseK, n);
  } else {
    if (!(p > 0)) {  // no strain yet: an infinite rate
      g = dgdx = std::numeric_limits<double>::infinity();
      dgdp = -g;
      return;
    }
    g = std::exp(n * (std::log(x * parameters_.inverseK) - invM * std::log(p)));
    dgdp = -n * invM * g / p;
  }
  dgdx = n * g / x;
}

template <class Residual>
double LemaitreViscoplasticity::root(const Residual& F, double q) const {
  const double tolerance = parameters_.tolerance;
  const int maxIterations = parameters_.maxIterations;
  auto failed = [&]() {
    return Error(std::string(parameters_.variables == LemaitreVariables::Norton ? "NORTON" : "LEMAITRE") +
                 ": the scalar equation of the viscous flow did not converge in ITER_INTE_MAXI = " +
                 std::to_string(maxIterations) + " iterations (RESI_INTE_RELA = " + format::shortest(tolerance) + ")");
  };
  double a = 0, fa = F(a), b = q * (1 - 1e-12), fb = F(b);
  if (std::fabs(fb) < tolerance) return b;
  int n = 1;
  // F(b) < 0 (a rate too small to show at b): secants beyond b until F changes sign.
  while (!(fb > 0)) {
    if (!(fb > fa)) throw failed();
    const double z = (a * fb - b * fa) / (fb - fa);
    ++n;
    a = b;
    fa = fb;
    b = z;
    fb = F(b);
    if (std::fabs(fb) < tolerance) return b;
    if (n > maxIterations) throw failed();
  }
  // Regula falsi in [a, b], the midpoint every third trial (F may be very nonlinear).
  for (;;) {
    // (An overflowing F, Lemaitre's rate at p ~ 0, takes the midpoint too.)
    const double z = n % 3 == 0 || !std::isfinite(fb) ? 0.5 * (a + b) : (a * fb - b * fa) / (fb - fa);
    ++n;
    const double fz = F(z);
    if (std::fabs(fz) < tolerance || std::fabs(b - a) <= tolerance * b) return z;
    if (n > maxIterations) throw failed();
    if (fz < 0) {
      a = z;
      fa = fz;
    } else {
      b = z;
      fb = fz;
    }
  }
}

void LemaitreViscoplasticity::integrateRungeKutta(const LawInput& in, LawOutput<VoigtTangent>& out,
                                                  bool withTangent) const {
  static constexpr double kNatural[7] = {0, 0, 0, 0, 0, 0, 0};
  const double* vn = in.previousVariables ? in.previousVariables : kNatural;
  const double dt = in.timeIncrement;
  if (dt < 0) throw Error("NORTON: negative time step " + format::shortest(dt) + " (the instants must increase)");
  const bool planeStrain = hypothesis_ == PlaneHypothesis::PlaneStrain;
  // Strains in code_aster's vector form (xx, yy, zz, sqrt 2 xy): the error norm is its.
  const double r2 = std::sqrt(2.0);
  const double end[4] = {in.strain(0, 0), in.strain(1, 1), planeStrain ? 0.0 : in.strainZZ, r2 * in.strain(0, 1)};
  const double de[4] = {in.strainIncrement(0, 0), in.strainIncrement(1, 1),
                        planeStrain ? 0.0 : in.strainIncrementZZ, r2 * in.strainIncrement(0, 1)};
  const double lambda = bulk_ - 2 * mu_ / 3;
  // y: the viscous strain (vector form) and p.
  using State = std::array<double, 5>;
  State y = {vn[0], vn[1], vn[2], r2 * vn[3], vn[6]};
  auto stressAt = [&](double x, const State& state, double sigma[4]) {
    const double fraction = dt > 0 ? x / dt : 1.0;
    double e[4];
    for (int i = 0; i < 4; ++i) e[i] = end[i] - de[i] + de[i] * fraction - state[i];
    const double tr = e[0] + e[1] + e[2];
    for (int i = 0; i < 4; ++i) sigma[i] = 2 * mu_ * e[i] + (i < 3 ? lambda * tr : 0.0);
  };
  auto rateAt = [&](double x, const State& state) {
    double sigma[4];
    stressAt(x, state, sigma);
    const double mean = (sigma[0] + sigma[1] + sigma[2]) / 3;
    double s[4];
    for (int i = 0; i < 4; ++i) s[i] = sigma[i] - (i < 3 ? mean : 0.0);
    const double q = std::sqrt(1.5 * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + s[3] * s[3]));
    State r = {0, 0, 0, 0, 0};
    if (q > std::numeric_limits<double>::min()) {
      const double dp = std::pow(q * parameters_.inverseK, parameters_.exponent);
      if (dp > 1e-10) {
        for (int i = 0; i < 4; ++i) r[i] = 1.5 * dp * s[i] / q;
        r[4] = dp;
      }
    }
    return r;
  };
  if (dt > 0 && parameters_.inverseK > 0) {
    const double eps = parameters_.tolerance;
    State scale;
    for (int i = 0; i < 5; ++i) scale[i] = std::max(1e-4, std::fabs(y[i]));
    double x = 0, h = dt;
    bool last = false, reuse = false;
    State a{}, start{};
    for (;;) {
      if (!reuse) {
        if (x + h >= dt) {
          h = dt - x;
          last = true;
        }
        start = y;
        a = rateAt(x, y);
      }
      State y1, error;
      for (int i = 0; i < 5; ++i) y1[i] = start[i] + a[i] * h;
      const State f = rateAt(x + h, y1);
      double w = 0;
      for (int i = 0; i < 5; ++i) {
        error[i] = (f[i] - a[i]) * 0.5 * h;
        w = std::max(w, std::fabs(error[i]) / scale[i]);
      }
      if (w <= eps) {
        for (int i = 0; i < 5; ++i) y[i] = y1[i] + error[i];
        x += h;
        reuse = false;
        if (last) break;
        h = std::min(dt, h * std::pow(std::max(w / eps, 1e-5), -0.2) * 0.9);
      } else {
        last = false;
        reuse = true;
        h *= std::pow(std::min(w / eps, 1e8), -0.2) * 0.9;
        if (h / dt < std::numeric_limits<double>::epsilon())
          throw Error("NORTON (RUNGE_KUTTA): the sub-step fell below the rounding of the time step " +
                      format::shortest(dt));
      }
    }
  }
  double sigma[4];
  stressAt(dt, y, sigma);
  out.stress << sigma[0], sigma[3] / r2, sigma[3] / r2, sigma[1];
  out.stressZZ = sigma[2];
  out.strainZZ = planeStrain ? 0.0 : in.strainZZ;
  if (out.variables) {
    for (int i = 0; i < 3; ++i) out.variables[i] = y[i];
    out.variables[3] = y[3] / r2;
    out.variables[4] = vn[4];
    out.variables[5] = vn[5];
    out.variables[6] = y[4];
  }
  if (!withTangent) return;
  VoigtTangent& D = out.tangent;
  D.setZero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) D(i, j) = lambda + (i == j ? 2 * mu_ : 0.0);
  D(kXY, kXY) = mu_;
}

void LemaitreViscoplasticity::integrate(const LawInput& in, LawOutput<VoigtTangent>& out, bool withTangent) const {
  if (parameters_.rungeKutta) {
    integrateRungeKutta(in, out, withTangent);
    return;
  }
  static constexpr double kNatural[7] = {0, 0, 0, 0, 0, 0, 0};
  const double* vn = in.previousVariables ? in.previousVariables : kNatural;
  const double* sn = in.previousStress;
  const double theta = parameters_.theta, dt = in.timeIncrement;
  if (dt < 0)
    throw Error("LEMAITRE/NORTON: negative time step " + format::shortest(dt) + " (the instants must increase)");
  const bool lemaitre = parameters_.variables == LemaitreVariables::Lemaitre;
  double de[4] = {in.strainIncrement(0, 0), in.strainIncrement(1, 1), in.strainIncrementZZ, in.strainIncrement(0, 1)};
  if (hypothesis_ == PlaneHypothesis::PlaneStrain) de[2] = 0.0;

  // The trial deviator at the theta point, s* = s_n + 2 mu theta de_dev, and its s*_eq.
  const double trDe = de[0] + de[1] + de[2];
  const double meanN = (sn[0] + sn[1] + sn[2]) / 3.0;
  double sN[4], trial[4];
  for (int i = 0; i < 4; ++i) {
    sN[i] = sn[i] - (i < 3 ? meanN : 0.0);
    trial[i] = sN[i] + 2 * mu_ * theta * (de[i] - (i < 3 ? trDe / 3.0 : 0.0));
  }
  const double q = std::sqrt(1.5 * contract(trial, trial));
  const double pn = lemaitre ? vn[0] : 0.0;
  const double c = 3 * mu_ * theta * dt;  // the factor of g in the scalar equation

  // x = s_theta_eq: the root in ]0, q] of F(x) = x - q + c g(x, p_n + (q - x) / (3 mu)),
  // F increasing, F(0) = -q, F(q) >= 0.
  auto residual = [&](double x) {
    if (c == 0) return x - q;
    double g, dgdx, dgdp;
    rate(x, pn + (q - x) / (3 * mu_), g, dgdx, dgdp);
    return x - q + c * g;
  };
  const double x = q > parameters_.tolerance ? root(residual, q) : 0.0;
  // s_theta = s* x / (x + c g(x)) (x / q at the exact root); the flow rate and its
  // derivatives at x give dx/dq, the tangent's.
  double ratio = 1.0, dxdq = 1.0;
  if (x != 0 && c > 0) {
    double g, dgdx, dgdp;
    rate(x, pn + (q - x) / (3 * mu_), g, dgdx, dgdp);
    ratio = x / (x + c * g);
    dxdq = (1 - theta * dt * dgdp) / (1 + c * dgdx - theta * dt * dgdp);
  }

  // s_{n+1} = s_n + (s_theta - s_n) / theta; the mean stress is elastic.
  const double mean = meanN + bulk_ * trDe;
  double stress[4];
  for (int i = 0; i < 4; ++i) stress[i] = sN[i] + (trial[i] * ratio - sN[i]) / theta + (i < 3 ? mean : 0.0);
  if (out.variables) {
    // d eps_v = (s* - s_theta) / (2 mu theta), its equivalent dp.
    const double dp = q * (1 - ratio) / (3 * mu_ * theta);
    if (lemaitre) {
      out.variables[0] = pn + dp;
      out.variables[1] = 0.0;
    } else {
      for (int i = 0; i < 4; ++i) out.variables[i] = vn[i] + trial[i] * (1 - ratio) / (2 * mu_ * theta);
      out.variables[4] = vn[4];
      out.variables[5] = vn[5];
      out.variables[6] = 0.0;
    }
  }
  out.stress << stress[0], stress[3], stress[3], stress[1];
  out.stressZZ = stress[2];
  out.strainZZ = hypothesis_ == PlaneHypothesis::PlaneStrain ? 0.0 : in.strainZZ;
  if (!withTangent) return;

  // D = K 1x1 + 2 mu [ratio I_dev + 3/2 (dx/dq - x/q) / q^2 s* x s*] on (e11, e22, e33, 2 e12).
  VoigtTangent& D = out.tangent;
  D.setZero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) D(i, j) = bulk_ + 2 * mu_ * ratio * ((i == j ? 1.0 : 0.0) - 1.0 / 3.0);
  D(kXY, kXY) = mu_ * ratio;
  if (x != 0) {
    const double coefficient = 2 * mu_ * 1.5 * (dxdq - x / q) / (q * q);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) D(i, j) += coefficient * trial[i] * trial[j];
  }
}

}  // namespace aster::mechanics
