#include "mechanics/visc_endo_lemaitre.hpp"

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

enum Variable { kEpspXX = 0, kEpspXY = 3, kEpspEq = 6, kEcroIsot = 7, kEndo = 8, kIndiPlas = 9 };
constexpr double kSqrt2 = 1.4142135623730951;

void require(bool ok, const std::string& what, double value) {
  if (!ok) throw Error("VISC_ENDO_LEMA: " + what + ", got " + format::shortest(value));
}

// The scalar equation's terms at u = x^(1/N) (x = dr), for the trial von Mises stress q.
struct Flow {
  double x = 0;                    // dr
  double stress = 0, dStress = 0;  // sigma~ and d sigma~/du
  double damage = 0, dDamage = 0;  // D and dD/du
  double g = 0, dG = 0;            // G and dG/du
};

}  // namespace

ViscEndoLemaitreParameters viscEndoLemaitreParameters(double young, double poisson, double n, double unSurK,
                                                      double unSurM, double yield, double rD, double aD) {
  require(n > 0, "LEMAITRE's N must be > 0", n);
  require(unSurK > 0, "LEMAITRE's UN_SUR_K must be > 0", unSurK);
  require(unSurM >= 0, "LEMAITRE's UN_SUR_M must be >= 0", unSurM);
  require(yield >= 0, "VISC_ENDO's SY must be >= 0", yield);
  require(rD > 0, "VISC_ENDO's R_D must be > 0 (the damage rate grows with the stress)", rD);
  require(aD > 0, "VISC_ENDO's A_D must be > 0", aD);
  ViscEndoLemaitreParameters p;
  p.young = young;
  p.poisson = poisson;
  p.n = n;
  p.k = 1.0 / unSurK;
  p.oneOverM = unSurM;
  p.yield = yield;
  p.rD = rD;
  p.aD = aD;
  return p;
}

ViscEndoLemaitre::ViscEndoLemaitre(ViscEndoLemaitreParameters parameters, PlaneHypothesis hypothesis)
    : parameters_(std::move(parameters)), hypothesis_(hypothesis) {
  if (hypothesis_ == PlaneHypothesis::PlaneStress)
    throw Error("VISC_ENDO_LEMA is not available in MODELISATION='C_PLAN' (code_aster has it in 3D, AXIS and D_PLAN)");
  const double E = parameters_.young, nu = parameters_.poisson;
  require(E > 0, "ELAS's E must be > 0", E);
  require(nu > -1 && nu < 0.5, "ELAS's NU must be in (-1, 0.5)", nu);
  if (parameters_.maxIterations < 1) throw Error("VISC_ENDO_LEMA: ITER_INTE_MAXI must be >= 1");
  mu_ = E / (2 * (1 + nu));
  bulk_ = E / (3 * (1 - 2 * nu));
}

std::vector<std::string> ViscEndoLemaitre::internalVariableNames() const {
  return {"EPSPXX", "EPSPYY", "EPSPZZ", "EPSPXY", "EPSPXZ", "EPSPYZ", "EPSPEQ", "ECROISOT", "ENDO", "INDIPLAS"};
}

void ViscEndoLemaitre::integrate(const LawInput& in, LawOutput<VoigtTangent>& out, bool withTangent) const {
  static constexpr double kNatural[10] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  static constexpr double kNoStress[4] = {0, 0, 0, 0};
  const ViscEndoLemaitreParameters& P = parameters_;
  const double* vn = in.previousVariables ? in.previousVariables : kNatural;
  const double* sn = in.previousStress ? in.previousStress : kNoStress;
  const double dt = in.timeIncrement;
  const double rn = vn[kEcroIsot];
  const double Dn = std::min(vn[kEndo], kDamageMax);

  // The effective trial state: the previous effective stress plus the elastic response.
  double de[4] = {in.strainIncrement(0, 0), in.strainIncrement(1, 1), in.strainIncrementZZ,
                  in.strainIncrement(0, 1)};
  if (hypothesis_ == PlaneHypothesis::PlaneStrain) de[2] = 0.0;
  const double trDe = de[0] + de[1] + de[2];
  const double meanN = (sn[0] + sn[1] + sn[2]) / 3.0;
  const double meanTrial = meanN / (1 - Dn) + bulk_ * trDe;
  double se[4];
  for (int i = 0; i < 4; ++i)
    se[i] = ((i < 3 ? sn[i] - meanN : sn[i]) / (1 - Dn)) + 2 * mu_ * (i < 3 ? de[i] - trDe / 3.0 : de[i]);
  const double q = std::sqrt(1.5 * contract(se, se));

  const double c = dt > 0 ? P.k * std::pow(dt, -1.0 / P.n) : 0.0;
  auto flowAt = [&](double u) {
    Flow f;
    f.x = std::pow(u, P.n);
    const double rx = rn + f.x;
    const double hardening = P.oneOverM > 0 ? std::pow(rx, P.oneOverM) : 1.0;
    f.stress = c * u * hardening + P.yield;
    f.dStress = c * hardening * (1 + P.n * P.oneOverM * (rx > 0 ? f.x / rx : 0.0));
    const double ratio = f.stress / P.aD;
    f.damage = Dn + dt * std::pow(ratio, P.rD);
    f.dDamage = f.stress > 0 ? dt * P.rD * std::pow(ratio, P.rD - 1) * f.dStress / P.aD : 0.0;
    f.g = (1 - f.damage) * (q - f.stress) - 3 * mu_ * f.x;
    const double dx = u > 0 ? P.n * f.x / u : (P.n == 1 ? 1.0 : 0.0);
    f.dG = -f.dDamage * (q - f.stress) - (1 - f.damage) * f.dStress - 3 * mu_ * dx;
    return f;
  };

  // The step: no flow (elastic with the damage D_n), flow, or the broken state.
  Flow flow;  // x = 0
  flow.damage = Dn;
  bool flows = dt > 0 && q > P.yield;
  int iterations = 0;
  const Flow atZero = flows ? flowAt(0.0) : flow;
  if (flows && atZero.damage >= kDamageMax) flow = atZero;  // broken at once
  else if (flows) {
    const double g0 = atZero.g;
    // Two bounds of the root: 3 mu x = (1 - D)(q - sigma~) <= (1 - D_n)(q - SY), and sigma~ < q
    // with sigma~ - SY >= c u r_n^(1/M) and >= c u^(1 + N/M). The smaller is close to the root
    // both for short steps (sigma~ near q) and long ones (the stress relaxed to SY), and G
    // is mostly concave: Newton from the right of the root then converges monotonically.
    double hi = std::pow(g0 / (3 * mu_), 1.0 / P.n);
    if (rn > 0 && P.oneOverM > 0) hi = std::min(hi, (q - P.yield) / (c * std::pow(rn, P.oneOverM)));
    hi = std::min(hi, std::pow((q - P.yield) / c, 1.0 / (1 + P.n * P.oneOverM)));
    double lo = 0, u = hi;
    bool solved = false;
    Flow best = atZero;
    for (iterations = 1; iterations <= P.maxIterations; ++iterations) {
      const Flow f = flowAt(u);
      const bool inside = f.damage < 1;  // beyond D = 1, G has no meaning
      if (!inside || f.g < 0) hi = u;
      else lo = u;
      if (inside && std::fabs(f.g) <= std::fabs(best.g)) best = f;
      if (inside && std::fabs(f.g) <= 1e-14 * q) {
        solved = true;
        break;
      }
      if (hi - lo <= 4 * std::numeric_limits<double>::epsilon() * hi) {
        best = flowAt(lo);
        solved = true;
        break;
      }
      double next = inside && f.dG < 0 ? u - f.g / f.dG : lo;
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      u = next;
    }
    if (!solved && !(std::fabs(best.g) <= P.tolerance * g0))
      throw Error("VISC_ENDO_LEMA: the viscoplastic step is not solved after ITER_INTE_MAXI = " +
                  std::to_string(P.maxIterations) + " iterations (residual " + format::shortest(best.g / g0) +
                  " of the initial one, RESI_INTE_RELA = " + format::shortest(P.tolerance) + ")");
    iterations = std::min(iterations, P.maxIterations);
    flow = best;
  }
  const bool broken = flow.damage >= kDamageMax;
  if (broken) {
    flow = Flow{};
    flow.damage = kDamageMax;
    flows = false;
  }

  // s = (1 - D) sigma~ s_e / q; the flow direction is 3/2 s_e / q.
  const double D = flow.damage;
  const double scale = flows ? flow.stress / q : 1.0;
  double stress[4];
  for (int i = 0; i < 4; ++i) stress[i] = (1 - D) * (scale * se[i] + (i < 3 ? meanTrial : 0.0));

  if (out.variables) {
    double* v = out.variables;
    for (int i = 0; i < 10; ++i) v[i] = vn[i];
    const double dp = flows ? flow.x / (1 - D) : 0.0;
    if (flows)
      for (int i = 0; i < 4; ++i) v[kEpspXX + i] += dp * 1.5 * se[i] / q * (i == 3 ? kSqrt2 : 1.0);
    v[kEpspEq] += dp;
    v[kEcroIsot] += flows ? flow.x : 0.0;
    v[kEndo] = D;
    v[kIndiPlas] = flows ? iterations : 0.0;
  }
  out.stress << stress[0], stress[3], stress[3], stress[1];
  out.stressZZ = stress[2];
  out.strainZZ = hypothesis_ == PlaneHypothesis::PlaneStrain ? 0.0 : in.strainZZ;
  if (!withTangent) return;

  // On (e11, e22, e33, 2 e12): (1 - D) [bulk 1x1 + 2 mu sigma~/q (I_dev - 3/2 N x N)] from the
  // trial direction, and the variations of sigma~ and D with q (dq = 3 mu N : de, N = s_e / q).
  VoigtTangent& T = out.tangent;
  T.setZero();
  const double shear = 2 * mu_ * (1 - D) * scale;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) T(i, j) = (1 - D) * bulk_ + shear * ((i == j ? 1.0 : 0.0) - 1.0 / 3.0);
  T(kXY, kXY) = shear / 2;
  if (flows && flow.dG < 0) {  // dG < 0 at every root but x = 0 (a bracket closed on 0)
    double N[4];
    for (int i = 0; i < 4; ++i) N[i] = se[i] / q;
    const double duDq = -(1 - D) / flow.dG;
    const double alongN = -1.5 * shear + 3 * mu_ * duDq * ((1 - D) * flow.dStress - flow.dDamage * flow.stress);
    const double mean = -3 * mu_ * duDq * flow.dDamage * meanTrial;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) T(i, j) += (alongN * N[i] + (i < 3 ? mean : 0.0)) * N[j];
  }
}

}  // namespace aster::mechanics
