#include "mechanics/von_mises_plasticity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "core/number_format.hpp"
#include "mechanics/plane_tensor.hpp"

namespace aster::mechanics {
namespace {

// H = E E_T / (E - E_T), the slope of R(p) for a uniaxial tangent modulus E_T = D_SIGM_EPSI.
double plasticSlope(double young, double tangent, const char* relation) {
  if (!(tangent < young))
    throw Error(std::string(relation) + ": ECRO_LINE's D_SIGM_EPSI = " + format::shortest(tangent) +
                " must be smaller than ELAS's E = " + format::shortest(young));
  return young * tangent / (young - tangent);
}

VonMisesParameters elasticPart(double young, double poisson) {
  VonMisesParameters p;
  p.young = young;
  p.poisson = poisson;
  return p;
}

IsotropicHardening hardeningOf(const TractionCurve& curve, double& young) {
  return IsotropicHardening::fromTractionCurve(curve.strain, curve.stress, curve.beyond, young);
}

// Where p, INDIPLAS and X sit among the internal variables.
struct Layout {
  int p, indicator, backStress;  // backStress: the first of XCINXX ... XCINYZ, -1 when none
};
Layout layoutOf(VonMisesVariables v) {
  switch (v) {
    case VonMisesVariables::Isotropic: return {0, 1, -1};
    case VonMisesVariables::Kinematic: return {7, 6, 0};
    case VonMisesVariables::Mixed: return {0, 1, 2};
  }
  return {0, 1, -1};
}

// A root of the increasing function f with f(0) < 0, from the guess xap: secant steps
// until the root is bracketed, then secant steps kept inside the bracket (bisection when
// one leaves it), until |f| < tolerance, or |f| is at the rounding of `scale` (a
// tolerance below rounding asks no more). This is the root finder code_aster's von
// Mises laws use in plane stress ("DEKKER"); the same iterates give the same stresses.
template <class F>
bool secantRoot(const F& f, double xap, double tolerance, double scale, int maxIterations, double& root) {
  const double floor = std::max(tolerance, 8 * std::numeric_limits<double>::epsilon() * scale);
  double x = 0, fx = f(x);
  if (std::fabs(fx) < floor) {
    root = 0;
    return true;
  }
  double y = xap, fy = f(y);
  int evaluations = 1;
  for (;;) {
    if (fy > 0) {
      double a = x, b = y;
      for (;;) {
        if (fx == fy) return false;
        double z = y - (y - x) * fy / (fy - fx);
        if ((z - a) * (z - b) > 0) z = 0.5 * (a + b);
        const double fz = f(z);
        ++evaluations;
        if (std::fabs(fz) < floor) {
          root = z;
          return true;
        }
        if (evaluations > maxIterations) return false;
        (fz < 0 ? a : b) = z;
        x = y;
        fx = fy;
        y = z;
        fy = fz;
      }
    }
    if (fy < fx || fx == fy) return false;
    const double z = y - (y - x) * fy / (fy - fx);
    ++evaluations;
    x = y;
    fx = fy;
    y = z;
    fy = f(z);
    if (std::fabs(fy) < floor) {
      root = z;
      return true;
    }
    if (evaluations > maxIterations) return false;
  }
}

}  // namespace

VonMisesParameters isotropicLinearParameters(double young, double poisson, double slope, double yield) {
  VonMisesParameters p = elasticPart(young, poisson);
  p.hardening = IsotropicHardening::linear(yield, plasticSlope(young, slope, "VMIS_ISOT_LINE"));
  return p;
}

VonMisesParameters isotropicTractionParameters(double poisson, const TractionCurve& curve) {
  VonMisesParameters p = elasticPart(0, poisson);
  p.hardening = hardeningOf(curve, p.young);
  return p;
}

VonMisesParameters kinematicLinearParameters(double young, double poisson, double slope, double yield) {
  if (!(slope > 0))
    throw Error("VMIS_CINE_LINE: ECRO_LINE's D_SIGM_EPSI = " + format::shortest(slope) +
                " must be > 0 (the kinematic hardening modulus)");
  VonMisesParameters p = elasticPart(young, poisson);
  p.hardening = IsotropicHardening::linear(yield, 0.0);
  p.prager = 2.0 / 3.0 * plasticSlope(young, slope, "VMIS_CINE_LINE");
  p.variables = VonMisesVariables::Kinematic;
  return p;
}

VonMisesParameters mixedLinearParameters(double young, double poisson, double slope, double yield, double prager) {
  VonMisesParameters p = elasticPart(young, poisson);
  p.hardening = IsotropicHardening::linear(yield, plasticSlope(young, slope, "VMIS_ECMI_LINE") - 1.5 * prager);
  p.prager = prager;
  p.variables = VonMisesVariables::Mixed;
  return p;
}

VonMisesParameters mixedTractionParameters(double poisson, const TractionCurve& curve, double prager) {
  VonMisesParameters p = elasticPart(0, poisson);
  p.hardening = hardeningOf(curve, p.young).lessKinematic(prager);
  p.prager = prager;
  p.variables = VonMisesVariables::Mixed;
  return p;
}

VonMisesPlasticity::VonMisesPlasticity(VonMisesParameters parameters, PlaneHypothesis hypothesis)
    : parameters_(std::move(parameters)), hypothesis_(hypothesis) {
  const double E = parameters_.young, nu = parameters_.poisson;
  if (!(E > 0)) throw Error("von Mises plasticity: Young's modulus E must be > 0, got " + format::shortest(E));
  if (!(nu > -1 && nu < 0.5))
    throw Error("von Mises plasticity: Poisson's ratio NU must be in (-1, 0.5), got " + format::shortest(nu));
  if (!(parameters_.prager >= 0))
    throw Error("von Mises plasticity: PRAGER's C must be >= 0, got " + format::shortest(parameters_.prager));
  if (!(parameters_.hardening.yield() > 0))
    throw Error("von Mises plasticity: the yield stress SY must be > 0, got " +
                format::shortest(parameters_.hardening.yield()));
  if (parameters_.maxIterations < 1) throw Error("von Mises plasticity: ITER_INTE_MAXI must be >= 1");
  mu_ = E / (2 * (1 + nu));
  bulk_ = E / (3 * (1 - 2 * nu));
}

int VonMisesPlasticity::internalVariableCount() const {
  return parameters_.variables == VonMisesVariables::Isotropic ? 2 : 8;
}

std::vector<std::string> VonMisesPlasticity::internalVariableNames() const {
  switch (parameters_.variables) {
    case VonMisesVariables::Isotropic: return {"EPSPEQ", "INDIPLAS"};
    case VonMisesVariables::Kinematic:
      return {"XCINXX", "XCINYY", "XCINZZ", "XCINXY", "XCINXZ", "XCINYZ", "INDIPLAS", "EPSPEQ"};
    case VonMisesVariables::Mixed:
      return {"EPSPEQ", "INDIPLAS", "XCINXX", "XCINYY", "XCINZZ", "XCINXY", "XCINXZ", "XCINYZ"};
  }
  return {};
}

void VonMisesPlasticity::returnMap(const LawInput& in, const double de[4], bool atRest, double stress[4],
                                   double* variables, VoigtTangent* tangent, bool& plastic) const {
  const Layout at = layoutOf(parameters_.variables);
  const double* vn = in.previousVariables;
  const double pn = vn[at.p];
  double Xn[4] = {0, 0, 0, 0};
  if (at.backStress >= 0)
    for (int i = 0; i < 4; ++i) Xn[i] = vn[at.backStress + i];

  // Trial state: the previous stress plus the elastic response to the whole increment.
  const double* sn = in.previousStress;
  const double trDe = de[0] + de[1] + de[2];
  const double mean = (sn[0] + sn[1] + sn[2]) / 3.0 + bulk_ * trDe;
  double s[4], xi[4];
  for (int i = 0; i < 4; ++i) {
    const double dev = i < 3 ? de[i] - trDe / 3.0 : de[i];
    s[i] = sn[i] - (i < 3 ? (sn[0] + sn[1] + sn[2]) / 3.0 : 0.0) + 2 * mu_ * dev;
    xi[i] = s[i] - Xn[i];
  }
  const double q = std::sqrt(1.5 * contract(xi, xi));
  const double h = 3 * mu_ + 1.5 * parameters_.prager;
  const double Rn = parameters_.hardening.value(pn);

  double dp = 0;
  plastic = q > Rn;
  if (plastic) dp = parameters_.hardening.returnIncrement(q, h, pn);
  // n = 3/2 xi / q; s = s_trial - 2 mu dp n; X = X_n + C dp n.
  const double ratio = plastic ? 1.5 * dp / q : 0.0;
  for (int i = 0; i < 4; ++i) {
    stress[i] = s[i] - 2 * mu_ * ratio * xi[i] + (i < 3 ? mean : 0.0);
  }
  if (variables) {
    for (int i = 0; i < internalVariableCount(); ++i) variables[i] = vn[i];
    variables[at.p] = pn + dp;
    variables[at.indicator] = plastic ? 1.0 : 0.0;
    if (at.backStress >= 0)
      for (int i = 0; i < 4; ++i) variables[at.backStress + i] = Xn[i] + parameters_.prager * ratio * xi[i];
  }
  if (!tangent) return;

  // D = K 1x1 + 2 mu theta I_dev - 2 mu thetaBar N x N on (e11, e22, e33, 2 e12).
  double theta = 1.0, thetaBar = 0.0;
  const double slope = parameters_.hardening.slope(pn + dp);
  if (plastic) {
    theta = 1.0 - 3 * mu_ * dp / q;
    thetaBar = 3 * mu_ / (h + slope) - 3 * mu_ * dp / q;
  } else if (atRest && vn[at.indicator] > 0.5 && q >= Rn * (1 - 1e-12)) {
    // No increment yet, on the yield surface after a plastic step (the prediction of a
    // step): the continuum elastic-plastic tangent, as code_aster's RIGI_MECA_TANG.
    thetaBar = 3 * mu_ / (h + slope);
  }
  VoigtTangent& D = *tangent;
  D.setZero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) D(i, j) = bulk_ + 2 * mu_ * theta * ((i == j ? 1.0 : 0.0) - 1.0 / 3.0);
  D(kXY, kXY) = mu_ * theta;
  if (thetaBar != 0) {
    const double norm = std::sqrt(contract(xi, xi));
    double N[4];
    for (int i = 0; i < 4; ++i) N[i] = xi[i] / norm;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) D(i, j) -= 2 * mu_ * thetaBar * N[i] * N[j];
  }
}

void VonMisesPlasticity::planeStressIsotropicReturn(const LawInput& in, double de[4], bool atRest,
                                                    double stress[4], double* variables,
                                                    VoigtTangent* tangent) const {
  const double E = parameters_.young, nu = parameters_.poisson;
  const IsotropicHardening& R = parameters_.hardening;
  const double pn = in.previousVariables[0];
  const double* sn = in.previousStress;
  // The elastic trial with the elastic guess of de_zz: deviatoric s_el, its q = (s_el)_eq.
  const double meanN = (sn[0] + sn[1] + sn[2]) / 3.0;
  double meanDe = (de[0] + de[1] + de[2]) / 3.0;
  double deDev[4], trial[4];
  for (int i = 0; i < 4; ++i) {
    deDev[i] = i < 3 ? de[i] - meanDe : de[i];
    trial[i] = sn[i] - (i < 3 ? meanN : 0.0) + 2 * mu_ * deDev[i];
  }
  double q = std::sqrt(1.5 * contract(trial, trial));
  const double Rn = R.value(pn);
  if (std::fabs(q - Rn) <= std::numeric_limits<double>::epsilon() * Rn) q = Rn;
  const bool plastic = !atRest && q > Rn;
  double dp = 0, Rp = Rn;
  if (plastic) {
    // With dp, s_zz = 0 asks de_zz += dx(dp); the yield condition is then one equation in dp.
    auto zzCorrection = [&](double x, double Rx) { return 3 * (1 - 2 * nu) * trial[kZZ] * x / (E * x + 2 * (1 - nu) * Rx); };
    auto yield = [&](double x) {
      const double Rx = R.value(pn + x), dx = zzCorrection(x, Rx);
      const double a = trial[kXX] - 2 * mu_ / 3 * dx, b = trial[kYY] - 2 * mu_ / 3 * dx;
      const double c = trial[kZZ] + 4 * mu_ / 3 * dx;
      return 3 * mu_ * x - std::sqrt(1.5 * (a * a + b * b + c * c + 2 * trial[kXY] * trial[kXY])) + Rx;
    };
    const double guess = R.returnIncrement(q, 3 * mu_, pn);  // the return without plane stress
    if (!secantRoot(yield, guess, parameters_.tolerance * R.yield(), q, parameters_.maxIterations, dp))
      throw Error("von Mises plasticity in plane stress: the yield equation is not solved to RESI_INTE_RELA x SY = " +
                  format::shortest(parameters_.tolerance * R.yield()) + " in ITER_INTE_MAXI = " +
                  std::to_string(parameters_.maxIterations) + " iterations");
    Rp = R.value(pn + dp);
    const double dx = zzCorrection(dp, Rp);
    de[kZZ] += dx;
    meanDe += dx / 3;
    deDev[kXX] -= dx / 3;
    deDev[kYY] -= dx / 3;
    deDev[kZZ] += 2 * dx / 3;
  }
  // The radial return with this dp: s = (s_n + 2 mu dev(de)) R / (R + 3 mu dp).
  const double shrink = Rp / (Rp + 3 * mu_ * dp);
  double s[4];
  for (int i = 0; i < 4; ++i) {
    s[i] = (sn[i] - (i < 3 ? meanN : 0.0) + 2 * mu_ * deDev[i]) * shrink;
    stress[i] = s[i] + (i < 3 ? meanN + 3 * bulk_ * meanDe : 0.0);
  }
  if (variables) {
    variables[0] = pn + dp;
    variables[1] = plastic ? 1.0 : 0.0;
  }
  if (!tangent) return;
  // The consistent tangent of the 3D return written with the final s (dp / R = (1/shrink - 1) / 3 mu),
  // kept elastic (divided by a) when s turns against the increment, condensed on s_zz = 0. At
  // rest after a plastic step, the continuum tangent at the previous stress (dp = 0, R = s_eq).
  VoigtTangent& D = *tangent;
  D.setZero();
  const double a = plastic ? 1 / shrink : 1.0;
  const bool continuum = atRest && in.previousVariables[1] > 0.5;
  if (continuum) Rp = std::sqrt(1.5 * contract(s, s));
  if ((plastic && contract(s, deDev) >= 0) || (continuum && Rp > 0)) {
    const double slope = R.slope(pn + dp);
    const double coef = -(9 * mu_ * mu_) / (3 * mu_ + slope) / (Rp * Rp) * (1 - dp * slope / Rp) / a;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) D(i, j) = coef * s[i] * s[j];
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) D(i, j) += bulk_ + 2 * mu_ / a * ((i == j ? 1.0 : 0.0) - 1.0 / 3.0);
  D(kXY, kXY) += mu_ / a;
  const Eigen::Vector4d column = D.col(kZZ);
  D -= column * D.row(kZZ) / D(kZZ, kZZ);
  D.row(kZZ).setZero();
  D.col(kZZ).setZero();
}

void VonMisesPlasticity::integrate(const LawInput& in, LawOutput<VoigtTangent>& out, bool withTangent) const {
  static constexpr double kNatural[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  LawInput input = in;
  if (!input.previousVariables) input.previousVariables = kNatural;
  double de[4] = {in.strainIncrement(0, 0), in.strainIncrement(1, 1), in.strainIncrementZZ, in.strainIncrement(0, 1)};
  double stress[4] = {0, 0, 0, 0};
  bool plastic = false;
  VoigtTangent D;
  const bool planeStress = hypothesis_ == PlaneHypothesis::PlaneStress;
  // No strain increment (in plane stress: in the plane): a step's prediction.
  const bool atRest = de[0] == 0 && de[1] == 0 && de[3] == 0 && (planeStress || de[2] == 0);
  if (!planeStress) {
    if (hypothesis_ == PlaneHypothesis::PlaneStrain) de[2] = 0.0;
    returnMap(input, de, atRest, stress, out.variables, withTangent ? &D : nullptr, plastic);
    out.strainZZ = hypothesis_ == PlaneHypothesis::PlaneStrain ? 0.0 : in.strainZZ;
  } else if (parameters_.variables == VonMisesVariables::Isotropic) {
    const double lambda = bulk_ - 2.0 * mu_ / 3.0;
    de[2] = -(lambda * (de[0] + de[1]) + in.previousStress[kZZ]) / (lambda + 2 * mu_);
    planeStressIsotropicReturn(input, de, atRest, stress, out.variables, withTangent ? &D : nullptr);
    out.strainZZ = (stress[0] + stress[1] + stress[2]) / (3 * bulk_) - in.strain(0, 0) - in.strain(1, 1);
  } else {
    // s_zz(de_zz) = 0 by Newton from the elastic guess (which makes the trial s_zz zero).
    const double lambda = bulk_ - 2.0 * mu_ / 3.0;
    de[2] = -(lambda * (de[0] + de[1]) + in.previousStress[kZZ]) / (lambda + 2 * mu_);
    double scale = 0;
    bool converged = false;
    for (int iteration = 0; iteration < parameters_.maxIterations && !converged; ++iteration) {
      returnMap(input, de, atRest, stress, out.variables, &D, plastic);
      scale = std::max({std::fabs(stress[0]), std::fabs(stress[1]), std::fabs(stress[3]),
                        parameters_.hardening.yield()});
      if (std::fabs(stress[2]) <= 1e-14 * scale) {
        converged = true;
        break;
      }
      const double step = stress[2] / D(kZZ, kZZ);
      de[2] -= step;
      converged = std::fabs(step) <= 1e-16 * std::max({std::fabs(de[0]), std::fabs(de[1]), std::fabs(de[2]),
                                                        std::fabs(de[3])});
      if (converged) returnMap(input, de, atRest, stress, out.variables, &D, plastic);
    }
    if (!(std::fabs(stress[2]) <= parameters_.tolerance * scale))
      throw Error("von Mises plasticity in plane stress: s_zz = " + format::shortest(stress[2]) +
                  " after ITER_INTE_MAXI iterations (RESI_INTE_RELA = " + format::shortest(parameters_.tolerance) +
                  ")");
    // The total zz strain: the plastic strain is deviatoric, so tr(strain) = tr(stress) / 3K.
    out.strainZZ = (stress[0] + stress[1] + stress[2]) / (3 * bulk_) - in.strain(0, 0) - in.strain(1, 1);
    if (withTangent) {
      const Eigen::Vector4d column = D.col(kZZ);
      D -= column * D.row(kZZ) / D(kZZ, kZZ);
      D.row(kZZ).setZero();
      D.col(kZZ).setZero();
    }
  }
  out.stress << stress[0], stress[3], stress[3], stress[1];
  out.stressZZ = stress[2];
  if (withTangent) out.tangent = D;
}

}  // namespace aster::mechanics
