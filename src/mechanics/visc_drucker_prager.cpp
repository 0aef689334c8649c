#include "mechanics/visc_drucker_prager.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/error.hpp"
#include "core/number_format.hpp"
#include "mechanics/plane_tensor.hpp"

namespace aster::mechanics {
namespace {

// The local equation in dp: F(x) = c <f1 - f2 x - f3 x^2 - f4 x^3>^N - x, and F'.
struct RateEquation {
  double c, n, f1, f2, f3, f4;
  double inner(double x) const { return f1 - f2 * x - f3 * x * x - f4 * x * x * x; }
  double value(double x) const { return c * std::pow(std::max(inner(x), 0.0), n) - x; }
  double derivative(double x) const {
    const double innerSlope = -f2 - 2 * f3 * x - 3 * f4 * x * x;
    return n * c * std::pow(std::max(inner(x), 0.0), n - 1) * innerSlope - 1;
  }
};

}  // namespace

int hardeningPiece(const ViscDruckerPragerMaterial& m, double p) { return p < m.pPeak ? 0 : p < m.pUlt ? 1 : 2; }

DruckerPragerHardening hardeningValues(const ViscDruckerPragerMaterial& m, double p) {
  switch (hardeningPiece(m, p)) {
    case 0: {
      const double t = p / m.pPeak;
      return {m.alpha0 + (m.alphaPeak - m.alpha0) * t, m.r0 + (m.rPeak - m.r0) * t,
              m.beta0 + (m.betaPeak - m.beta0) * t};
    }
    case 1: {
      const double t = (p - m.pPeak) / (m.pUlt - m.pPeak);
      return {m.alphaPeak + (m.alphaUlt - m.alphaPeak) * t, m.rPeak + (m.rUlt - m.rPeak) * t,
              m.betaPeak + (m.betaUlt - m.betaPeak) * t};
    }
    default: return {m.alphaUlt, m.rUlt, m.betaUlt};
  }
}

DruckerPragerHardening hardeningSlopes(const ViscDruckerPragerMaterial& m, int piece) {
  switch (piece) {
    case 0:
      return {(m.alphaPeak - m.alpha0) / m.pPeak, (m.rPeak - m.r0) / m.pPeak, (m.betaPeak - m.beta0) / m.pPeak};
    case 1: {
      const double length = m.pUlt - m.pPeak;
      return {(m.alphaUlt - m.alphaPeak) / length, (m.rUlt - m.rPeak) / length, (m.betaUlt - m.betaPeak) / length};
    }
    default: return {0, 0, 0};
  }
}

ViscDruckerPrager::ViscDruckerPrager(ViscDruckerPragerParameters parameters, PlaneHypothesis hypothesis)
    : parameters_(std::move(parameters)), hypothesis_(hypothesis) {
  const double E = parameters_.young, nu = parameters_.poisson;
  const ViscDruckerPragerMaterial& m = parameters_.material;
  if (hypothesis_ == PlaneHypothesis::PlaneStress)
    throw Error("VISC_DRUC_PRAG is not available in plane stress (C_PLAN): code_aster has it in 3D, AXIS and D_PLAN");
  if (!(E > 0)) throw Error("VISC_DRUC_PRAG: Young's modulus E must be > 0, got " + format::shortest(E));
  if (!(nu > -1 && nu < 0.5))
    throw Error("VISC_DRUC_PRAG: Poisson's ratio NU must be in (-1, 0.5), got " + format::shortest(nu));
  if (!(m.pref > 0)) throw Error("VISC_DRUC_PRAG: PREF must be > 0, got " + format::shortest(m.pref));
  if (!(m.a >= 0)) throw Error("VISC_DRUC_PRAG: A must be >= 0, got " + format::shortest(m.a));
  if (!(m.n > 0)) throw Error("VISC_DRUC_PRAG: N must be > 0, got " + format::shortest(m.n));
  if (!(m.pPeak > 0 && m.pUlt > m.pPeak))
    throw Error("VISC_DRUC_PRAG: 0 < P_PIC < P_ULT is required, got P_PIC = " + format::shortest(m.pPeak) +
                ", P_ULT = " + format::shortest(m.pUlt));
  if (parameters_.maxIterations < 1) throw Error("VISC_DRUC_PRAG: ITER_INTE_MAXI must be >= 1");
  mu_ = E / (2 * (1 + nu));
  bulk_ = E / (3 * (1 - 2 * nu));
}

std::vector<std::string> ViscDruckerPrager::internalVariableNames() const {
  return {"EPSPEQ", "INDIPLAS", "POS", "NBITER"};
}

double ViscDruckerPrager::solve(double f1, double i1e, double dt, const DruckerPragerHardening& atStart,
                                const DruckerPragerHardening& slopes, int& nbIter) const {
  const ViscDruckerPragerMaterial& m = parameters_.material;
  const double nineK = 9 * bulk_;
  const RateEquation F{m.a * dt / std::pow(m.pref, m.n),
                       m.n,
                       f1,
                       3 * mu_ + slopes.r - slopes.alpha * i1e + nineK * atStart.alpha * atStart.beta,
                       nineK * (atStart.alpha * slopes.beta + atStart.beta * slopes.alpha),
                       nineK * slopes.alpha * slopes.beta};
  // The root lies in [0, the rate at the trial state times dt]: F(0) > 0 and F(upper) <= 0
  // while the criterion decreases with dp.
  double lower = 0, upper = m.a * std::pow(f1 / m.pref, m.n) * dt;
  const double scale = F.value(0);  // the residual the tolerance is relative to
  const double tol = parameters_.tolerance;
  if (!(scale > 0)) {  // a rate below the smallest double: no flow
    nbIter = 1;
    return 0.0;
  }
  if (std::fabs(F.value(upper) / scale) <= tol) {
    nbIter = 1;
    return upper;
  }
  double x = 0, f = scale, slope = F.derivative(0);
  for (int iteration = 1; iteration <= parameters_.maxIterations; ++iteration) {
    if (std::fabs(f / scale) < tol) {
      nbIter = iteration;
      return x;
    }
    x -= f / slope;
    if (!(x > lower && x < upper)) x = 0.5 * (lower + upper);  // Newton left the bracket: bisect
    f = F.value(x);
    slope = F.derivative(x);
    const double atLower = F.value(lower);
    const bool sameSign = (f > 0) == (atLower > 0);
    (sameSign ? lower : upper) = x;
  }
  throw Error("VISC_DRUC_PRAG: the local Newton on the viscoplastic increment did not converge in ITER_INTE_MAXI = " +
              std::to_string(parameters_.maxIterations) + " iterations (RESI_INTE_RELA = " + format::shortest(tol) +
              ")");
}

void ViscDruckerPrager::update(const LawInput& in, const double de[4], double stress[4], double* variables,
                               VoigtTangent* tangent) const {
  const ViscDruckerPragerMaterial& m = parameters_.material;
  static constexpr double kNatural[4] = {0, 0, 0, 0};
  const double* vn = in.previousVariables ? in.previousVariables : kNatural;
  const double* sn = in.previousStress ? in.previousStress : kNatural;
  const double pn = vn[0];

  // Trial state: the previous stress plus the elastic response to the whole increment.
  const double trDe = de[0] + de[1] + de[2];
  const double i1e = sn[0] + sn[1] + sn[2] + 3 * bulk_ * trDe;
  double s[4];
  for (int i = 0; i < 4; ++i)
    s[i] = sn[i] - (i < 3 ? (sn[0] + sn[1] + sn[2]) / 3.0 : 0.0) + 2 * mu_ * (i < 3 ? de[i] - trDe / 3.0 : de[i]);
  const double qe = std::sqrt(1.5 * contract(s, s));
  const DruckerPragerHardening atStart = hardeningValues(m, pn);
  const double f1 = qe + atStart.alpha * i1e - atStart.r;
  const double dt = in.timeIncrement;

  double dp = 0;
  int nbIter = 0, piece = hardeningPiece(m, pn);
  const bool viscoplastic = f1 > 0 && dt > 0 && m.a > 0;
  if (viscoplastic) {
    // The slopes of the piece where the step ends: solve again while dp leaves the piece.
    for (int attempt = 0; attempt < 3; ++attempt) {
      dp = solve(f1, i1e, dt, atStart, hardeningSlopes(m, piece), nbIter);
      const int endPiece = hardeningPiece(m, pn + dp);
      if (endPiece == piece) break;
      piece = endPiece;
    }
    if (!(3 * mu_ * dp < qe))
      throw Error("VISC_DRUC_PRAG: the viscoplastic return crosses the apex of the cone (3 mu dp = " +
                  format::shortest(3 * mu_ * dp) + " >= q_trial = " + format::shortest(qe) + ")");
  }
  const double p = pn + dp;
  const double beta = hardeningValues(m, p).beta;
  const double shrink = viscoplastic ? 1 - 3 * mu_ * dp / qe : 1.0;
  const double i1 = i1e - 9 * bulk_ * beta * dp;
  for (int i = 0; i < 4; ++i) stress[i] = s[i] * shrink + (i < 3 ? i1 / 3 : 0.0);
  if (variables) {
    variables[0] = p;
    variables[1] = viscoplastic ? 1.0 : 0.0;
    variables[2] = p < m.pPeak ? 1.0 : p < m.pUlt ? 2.0 : 3.0;
    variables[3] = nbIter;
  }
  if (!tangent) return;

  // Voigt columns j: strains e11, e22, e33, 2 e12.
  VoigtTangent& D = *tangent;
  double devStiff[4][4] = {};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) devStiff[i][j] = 2 * mu_ * ((i == j ? 1.0 : 0.0) - 1.0 / 3.0);
  devStiff[3][3] = mu_;
  double dI1e[4] = {3 * bulk_, 3 * bulk_, 3 * bulk_, 0};
  double dqe[4], ddp[4] = {0, 0, 0, 0};
  for (int j = 0; j < 4; ++j) dqe[j] = qe > 0 ? 3 * mu_ * s[j] / qe : 0.0;
  double dBeta = 0;
  if (viscoplastic) {
    // dp(e) from F(dp; q_e, I1_e) = 0: ddp = -(dF/de) / (dF/ddp).
    const DruckerPragerHardening slopes = hardeningSlopes(m, piece);
    const double nineK = 9 * bulk_;
    const double f2 = 3 * mu_ + slopes.r - slopes.alpha * i1e + nineK * atStart.alpha * atStart.beta;
    const double f3 = nineK * (atStart.alpha * slopes.beta + atStart.beta * slopes.alpha);
    const double f4 = nineK * slopes.alpha * slopes.beta;
    const double c = m.a * dt / std::pow(m.pref, m.n);
    const double inner = f1 - f2 * dp - f3 * dp * dp - f4 * dp * dp * dp;
    const double rate = m.n * c * std::pow(std::max(inner, 0.0), m.n - 1);
    const double dFdp = rate * (-f2 - 2 * f3 * dp - 3 * f4 * dp * dp) - 1;
    for (int j = 0; j < 4; ++j) ddp[j] = -rate * (dqe[j] + (atStart.alpha + slopes.alpha * dp) * dI1e[j]) / dFdp;
    dBeta = hardeningSlopes(m, hardeningPiece(m, p)).beta;
  }
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double v = devStiff[i][j] * shrink;
      if (viscoplastic) v += s[i] * (-3 * mu_ / qe * ddp[j] + 3 * mu_ * dp / (qe * qe) * dqe[j]);
      if (i < 3) v += (dI1e[j] - 9 * bulk_ * (beta + dBeta * dp) * ddp[j]) / 3;
      D(i, j) = v;
    }
}

VoigtTangent ViscDruckerPrager::exactTangent(const LawInput& in) const {
  double de[4] = {in.strainIncrement(0, 0), in.strainIncrement(1, 1), in.strainIncrementZZ, in.strainIncrement(0, 1)};
  if (hypothesis_ == PlaneHypothesis::PlaneStrain) de[2] = 0.0;
  double stress[4];
  VoigtTangent D;
  update(in, de, stress, nullptr, &D);
  return D;
}

void ViscDruckerPrager::integrate(const LawInput& in, LawOutput<VoigtTangent>& out, bool withTangent) const {
  double de[4] = {in.strainIncrement(0, 0), in.strainIncrement(1, 1), in.strainIncrementZZ, in.strainIncrement(0, 1)};
  if (hypothesis_ == PlaneHypothesis::PlaneStrain) de[2] = 0.0;
  // No strain increment: a step's prediction, whose matrix is the elastic one.
  const bool atRest = de[0] == 0 && de[1] == 0 && de[2] == 0 && de[3] == 0;
  double stress[4];
  VoigtTangent D;
  update(in, de, stress, out.variables, withTangent ? &D : nullptr);
  out.stress << stress[0], stress[3], stress[3], stress[1];
  out.stressZZ = stress[2];
  out.strainZZ = hypothesis_ == PlaneHypothesis::PlaneStrain ? 0.0 : in.strainZZ;
  if (!withTangent) return;
  if (atRest) {
    const double lambda = bulk_ - 2 * mu_ / 3;
    D.setZero();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) D(i, j) = lambda + (i == j ? 2 * mu_ : 0.0);
    D(kXY, kXY) = mu_;
  }
  out.tangent = 0.5 * (D + D.transpose());
}

}  // namespace aster::mechanics
