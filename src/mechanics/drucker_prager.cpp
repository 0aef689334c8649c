#include "mechanics/drucker_prager.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "core/error.hpp"
#include "core/number_format.hpp"
#include "mechanics/plane_tensor.hpp"

namespace aster::mechanics {
namespace {

enum Mode { kElastic = 0, kCone = 1, kApex = 2 };

}  // namespace

double DruckerPragerParameters::radius(double p) const {
  const double x = std::min(p, ultimateStrain);
  if (hardening == Hardening::Linear) return yield + slope * x;
  const double shape = 1.0 - (1.0 - std::sqrt(ultimateYield / yield)) * x / ultimateStrain;
  return yield * shape * shape;
}

double DruckerPragerParameters::radiusSlope(double p) const {
  if (p >= ultimateStrain) return 0.0;
  if (hardening == Hardening::Linear) return slope;
  const double a = 1.0 - std::sqrt(ultimateYield / yield);
  return -2.0 * yield * a / ultimateStrain * (1.0 - a * p / ultimateStrain);
}

double DruckerPragerParameters::flowVolumetric(double p) const {
  if (associated) return alpha;
  return p < ultimateStrain ? dilatancy * (1.0 - p / ultimateStrain) : 0.0;
}

double DruckerPragerParameters::flowVolumetricSlope(double p) const {
  if (associated || p >= ultimateStrain) return 0.0;
  return -dilatancy / ultimateStrain;
}

DruckerPrager::DruckerPrager(DruckerPragerParameters parameters, PlaneHypothesis hypothesis)
    : parameters_(std::move(parameters)), hypothesis_(hypothesis) {
  const auto& p = parameters_;
  const char* name = p.associated ? "DRUCK_PRAGER" : "DRUCK_PRAG_N_A";
  auto require = [&](bool ok, const std::string& what) {
    if (!ok) throw Error(std::string(name) + ": " + what);
  };
  require(p.young > 0, "Young's modulus E must be > 0, got " + format::shortest(p.young));
  require(p.poisson > -1 && p.poisson < 0.5, "Poisson's ratio NU must be in (-1, 0.5), got " +
                                                 format::shortest(p.poisson));
  require(p.yield > 0, "DRUCK_PRAGER's SY must be > 0, got " + format::shortest(p.yield));
  require(p.ultimateStrain > 0, "DRUCK_PRAGER's P_ULTM must be > 0, got " + format::shortest(p.ultimateStrain));
  if (p.hardening == DruckerPragerParameters::Hardening::Parabolic)
    require(p.ultimateYield > 0, "DRUCK_PRAGER's SY_ULTM must be > 0, got " + format::shortest(p.ultimateYield));
  require(p.associated || p.hardening == DruckerPragerParameters::Hardening::Parabolic,
          "the non-associated law takes ECROUISSAGE='PARABOLIQUE' only (as in code_aster)");
  require(hypothesis != PlaneHypothesis::PlaneStress,
          "not available in C_PLAN (code_aster has it in 3D, D_PLAN and AXIS)");
  mu_ = p.young / (2 * (1 + p.poisson));
  bulk_ = p.young / (3 * (1 - 2 * p.poisson));
  // On the cone the multiplier's equation must stay solvable: 3 mu + 9 K A^2 + H > 0.
  if (p.hardening == DruckerPragerParameters::Hardening::Linear)
    require(3 * mu_ + 9 * bulk_ * p.alpha * p.alpha + p.slope > 0,
            "H = " + format::shortest(p.slope) + " softens faster than the elastic response (3 mu + 9 K ALPHA^2 + H <= 0)");
}

template <class Residual>
double DruckerPrager::solveReturn(const Residual& residual, double scale) const {
  double lo = 0.0, hi = std::numeric_limits<double>::infinity(), x = 0.0;
  for (int iteration = 0; iteration < 200; ++iteration) {
    double g = 0, dg = 0;
    residual(x, g, dg);
    if (std::fabs(g) <= 1e-14 * scale) return x;
    (g > 0 ? lo : hi) = x;
    double next = dg < 0 ? x - g / dg : std::numeric_limits<double>::quiet_NaN();
    if (!(next > lo && next < hi)) {
      if (!std::isfinite(hi))
        throw Error(std::string(parameters_.associated ? "DRUCK_PRAGER" : "DRUCK_PRAG_N_A") +
                    ": the return to the yield surface has no solution (softening or no dilatancy left)");
      next = 0.5 * (lo + hi);
    }
    if (std::fabs(next - x) <= 1e-15 * std::fabs(next)) return next;
    x = next;
  }
  throw Error(std::string(parameters_.associated ? "DRUCK_PRAGER" : "DRUCK_PRAG_N_A") +
              ": the return to the yield surface did not converge");
}

void DruckerPrager::integrate(const LawInput& in, LawOutput<VoigtTangent>& out, bool withTangent) const {
  static constexpr double kNatural[3] = {0, 0, 0};
  const DruckerPragerParameters& P = parameters_;
  const double* vn = in.previousVariables ? in.previousVariables : kNatural;
  const double* sn = in.previousStress;
  double de[4] = {in.strainIncrement(0, 0), in.strainIncrement(1, 1), in.strainIncrementZZ, in.strainIncrement(0, 1)};
  if (hypothesis_ == PlaneHypothesis::PlaneStrain) de[2] = 0.0;
  const bool atRest = de[0] == 0 && de[1] == 0 && de[2] == 0 && de[3] == 0;

  // The elastic trial state.
  const double trDe = de[0] + de[1] + de[2];
  const double I1e = sn[0] + sn[1] + sn[2] + 3 * bulk_ * trDe;
  double se[4];
  for (int i = 0; i < 4; ++i)
    se[i] = sn[i] - (i < 3 ? (sn[0] + sn[1] + sn[2]) / 3.0 : 0.0) + 2 * mu_ * (i < 3 ? de[i] - trDe / 3.0 : de[i]);
  const double qe = std::sqrt(1.5 * contract(se, se));
  const double pn = vn[0];
  const double A = P.alpha, K = bulk_, mu = mu_;
  const double Rn = P.radius(pn);
  const double f = qe + A * I1e - Rn;
  const double scale = std::max({Rn, qe, std::fabs(A * I1e)});

  Mode mode = kElastic;
  double dp = 0;
  if (f > 0) {
    mode = kCone;
    dp = solveReturn(
        [&](double x, double& g, double& dg) {
          const double p = pn + x, B = P.flowVolumetric(p), dB = P.flowVolumetricSlope(p);
          g = qe - 3 * mu * x + A * (I1e - 9 * K * B * x) - P.radius(p);
          dg = -3 * mu - 9 * K * A * (B + dB * x) - P.radiusSlope(p);
        },
        scale);
    if (qe - 3 * mu * dp < 0) {
      mode = kApex;
      dp = solveReturn(
          [&](double x, double& g, double& dg) {
            const double p = pn + x, B = P.flowVolumetric(p), dB = P.flowVolumetricSlope(p);
            g = A * (I1e - 9 * K * B * x) - P.radius(p);
            dg = -9 * K * A * (B + dB * x) - P.radiusSlope(p);
          },
          scale);
    }
  }
  const double p = pn + dp, B = P.flowVolumetric(p);
  const double mean = I1e / 3.0 - 3 * K * B * dp;
  const double deviatoric = mode == kApex ? 0.0 : mode == kCone ? 1.0 - 3 * mu * dp / qe : 1.0;
  double stress[4];
  for (int i = 0; i < 4; ++i) stress[i] = deviatoric * se[i] + (i < 3 ? mean : 0.0);
  if (out.variables) {
    out.variables[0] = p;
    out.variables[1] = vn[1] + 3 * B * dp;
    out.variables[2] = mode;
  }
  out.stress << stress[0], stress[3], stress[3], stress[1];
  out.stressZZ = stress[2];
  out.strainZZ = hypothesis_ == PlaneHypothesis::PlaneStrain ? 0.0 : in.strainZZ;
  if (!withTangent) return;

  // No increment yet (a step's prediction) after a plastic step: the continuum
  // elastic-plastic tangent (dp = 0) at the previous stress, of the previous step's mode
  // (INDIPLAS) whatever the yield function there, as code_aster's RIGI_MECA_TANG.
  Mode tangentMode = mode;
  if (atRest && mode == kElastic && vn[2] > 0.5)
    tangentMode = vn[2] > 1.5 ? kApex : (qe > 0 ? kCone : kElastic);

  VoigtTangent& D = out.tangent;
  D.setZero();
  const double dB = P.flowVolumetricSlope(p);
  const double flowRate = B + dB * dp;  // d(B dp)/d(dp)
  if (tangentMode == kApex) {
    if (p >= P.ultimateStrain) {
      // Nothing left to harden: the exact tangent is zero; code_aster's stand-in.
      const double young = P.young * 1e-6, k = young / (3 * (1 - 2 * P.poisson)), m = young / (2 * (1 + P.poisson));
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) D(i, j) = k + 2 * m * ((i == j ? 1.0 : 0.0) - 1.0 / 3.0);
      D(kXY, kXY) = m;
      return;
    }
    const double ha = 9 * K * A * flowRate + P.radiusSlope(p);
    const double bulk = K * (1.0 - 9 * K * A * flowRate / ha);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) D(i, j) = bulk;
    return;
  }
  const double theta = tangentMode == kCone ? 1.0 - 3 * mu * dp / qe : 1.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) D(i, j) = K + 2 * mu * theta * ((i == j ? 1.0 : 0.0) - 1.0 / 3.0);
  D(kXY, kXY) = mu * theta;
  if (tangentMode != kCone) return;
  const double h = 3 * mu + 9 * K * A * flowRate + P.radiusSlope(p);
  const double c = 9 * mu * mu * dp / (qe * qe * qe);
  double v[4], w[4];
  for (int i = 0; i < 4; ++i) {
    v[i] = 3 * mu * se[i] / qe + (i < 3 ? 3 * K * A : 0.0);
    w[i] = 3 * mu * se[i] / qe + (i < 3 ? 3 * K * flowRate : 0.0);
  }
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) D(i, j) += c * se[i] * se[j] - w[i] * v[j] / h;
}

}  // namespace aster::mechanics
