// VISC_ENDO_LEMA at one material point, against closed forms derived by hand
// and central finite differences.
//
// Uniaxial creep under a constant stress sigma (s_xx = sigma, the rest zero; the
// point is driven by Newton on its normal strains with the law's tangent, in
// AXIS where the hoop strain is free). The effective von Mises stress is
// sigma / (1 - D), the flow direction 3/2 s / s_eq has xx component 1, so:
//  - without threshold nor hardening (SY = 0, UN_SUR_M = 0), with a = sigma / A_D,
//    b = (sigma / K)^N:
//      D' = (a / (1 - D))^R  =>  (1 - D)^(R+1) = 1 - t / t_c,  t_c = 1 / ((R + 1) a^R),
//      p' = eps_vp_xx' = b (1 - D)^-(N+1)  =>  p = b t_c (R+1)/(N-R) [(1 - t/t_c)^(-(N-R)/(R+1)) - 1],
//      r' = b (1 - D)^-N                   =>  r = b t_c (R+1)/(N-R-1) [(1 - t/t_c)^(-(N-R-1)/(R+1)) - 1],
//    and the implicit steps carry sigma until a few steps before t_c, each step's damage
//    the root of the scalar implicit equation of D alone (below);
//  - without damage (A_D huge), with SY and UN_SUR_M = 1/M:
//      r^(N/M) r' = ((sigma - SY) / K)^N  =>  r = [(1 + N/M) ((sigma - SY)/K)^N t]^(1 / (1 + N/M)).
// The strain is eps_xx = sigma / ((1 - D) E) + p, eps_yy = -NU sigma / ((1 - D) E) - p / 2.
// The implicit Euler scheme is first order in the time step: the error on D at a
// given instant halves with the step.
#include <gtest/gtest.h>

#include <Eigen/LU>

#include <cmath>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "mechanics/visc_endo_lemaitre.hpp"

using namespace aster;
using namespace aster::mechanics;

namespace {

constexpr double kE = 200e3, kNu = 0.3;

// One material point and its accepted state.
struct Point {
  const BehaviourLaw& law;
  double strain[4] = {0, 0, 0, 0};  // xx, yy, zz, xy (tensor)
  double stress[4] = {0, 0, 0, 0};
  std::vector<double> variables;
  double time = 0;
  explicit Point(const BehaviourLaw& l) : law(l), variables(l.internalVariableCount(), 0.0) {}

  LawOutput<VoigtTangent> at(const double e[4], double t, std::vector<double>& newVariables) const {
    LawInput in;
    in.strain << e[0], e[3], e[3], e[1];
    in.strainZZ = e[2];
    in.strainIncrement << e[0] - strain[0], e[3] - strain[3], e[3] - strain[3], e[1] - strain[1];
    in.strainIncrementZZ = e[2] - strain[2];
    in.previousStress = stress;
    in.previousVariables = variables.data();
    in.time = t;
    in.timeIncrement = t - time;
    LawOutput<VoigtTangent> out;
    newVariables.assign(variables.size(), 0.0);
    out.variables = newVariables.data();
    law.integrate(in, out, true);
    return out;
  }
  static void stressOf(const LawOutput<VoigtTangent>& out, double s[4]) {
    s[0] = out.stress(0, 0);
    s[1] = out.stress(1, 1);
    s[2] = out.stressZZ;
    s[3] = out.stress(0, 1);
  }
  void accept(const double e[4], double t, const LawOutput<VoigtTangent>& out, const std::vector<double>& v) {
    for (int i = 0; i < 4; ++i) strain[i] = e[i];
    stressOf(out, stress);
    variables = v;
    time = t;
  }

  // The step to instant t under the uniaxial stress s_xx = sigma (AXIS: xx, yy, zz free,
  // xy = 0), by Newton on the normal strains with the law's tangent; false (the state
  // unchanged) when no strain carries sigma.
  void uniaxialStep(double sigma, double t) {
    if (!tryUniaxialStep(sigma, t)) FAIL() << "the uniaxial step to t = " << t << " did not converge";
  }
  bool tryUniaxialStep(double sigma, double t) {
    double e[4] = {strain[0], strain[1], strain[2], 0};
    std::vector<double> v;
    for (int iteration = 0; iteration < 50; ++iteration) {
      const auto out = at(e, t, v);
      double s[4];
      stressOf(out, s);
      const Eigen::Vector3d r(s[0] - sigma, s[1], s[2]);
      if (r.lpNorm<Eigen::Infinity>() <= 1e-10 * sigma) {
        accept(e, t, out, v);
        return true;
      }
      const Eigen::Vector3d d = out.tangent.topLeftCorner<3, 3>().lu().solve(-r);
      for (int i = 0; i < 3; ++i) e[i] += d(i);
    }
    return false;
  }
};

ViscEndoLemaitre lawOf(double n, double unSurK, double unSurM, double sy, double rD, double aD,
                       PlaneHypothesis h = PlaneHypothesis::Axisymmetric) {
  auto p = viscEndoLemaitreParameters(kE, kNu, n, unSurK, unSurM, sy, rD, aD);
  return ViscEndoLemaitre(p, h);
}

// Creep with damage: N = 4, K = 2000, R_D = 2, A_D = 1000 under sigma = 200.
constexpr double kN = 4, kK = 2000, kR = 2, kA = 1000, kSigma = 200;
const double kB = std::pow(kSigma / kK, kN);
const double kTc = 1.0 / ((kR + 1) * std::pow(kSigma / kA, kR));
double damageAt(double t) { return 1 - std::pow(1 - t / kTc, 1 / (kR + 1)); }
double pAt(double t) { return kB * kTc * (kR + 1) / (kN - kR) * (std::pow(1 - t / kTc, -(kN - kR) / (kR + 1)) - 1); }
double rAt(double t) {
  return kB * kTc * (kR + 1) / (kN - kR - 1) * (std::pow(1 - t / kTc, -(kN - kR - 1) / (kR + 1)) - 1);
}

// D at t = 0.8 t_c with `steps` equal steps after the instantaneous loading.
double damageWithSteps(int steps) {
  const auto law = lawOf(kN, 1 / kK, 0, 0, kR, kA);
  Point point(law);
  point.uniaxialStep(kSigma, 0.0);
  const double end = 0.8 * kTc;
  for (int k = 1; k <= steps; ++k) point.uniaxialStep(kSigma, end * k / steps);
  return point.variables[8];
}

}  // namespace

TEST(ViscEndoLemaitre, NamesItsVariablesAsCodeAster) {
  const auto law = lawOf(kN, 1 / kK, 0, 0, kR, kA);
  EXPECT_EQ(law.internalVariableNames(),
            (std::vector<std::string>{"EPSPXX", "EPSPYY", "EPSPZZ", "EPSPXY", "EPSPXZ", "EPSPYZ", "EPSPEQ", "ECROISOT",
                                      "ENDO", "INDIPLAS"}));
  EXPECT_EQ(law.internalVariableCount(), 10);
}

TEST(ViscEndoLemaitre, InstantaneousLoadingIsElastic) {
  const auto law = lawOf(kN, 1 / kK, 0, 0, kR, kA);
  Point point(law);
  point.uniaxialStep(kSigma, 0.0);  // no time: no flow, no damage
  EXPECT_NEAR(point.strain[0], kSigma / kE, 1e-15);
  EXPECT_NEAR(point.strain[1], -kNu * kSigma / kE, 1e-15);
  for (double v : point.variables) EXPECT_EQ(v, 0.0);
}

TEST(ViscEndoLemaitre, UniaxialCreepFollowsTheClosedForm) {
  const auto law = lawOf(kN, 1 / kK, 0, 0, kR, kA);
  Point point(law);
  point.uniaxialStep(kSigma, 0.0);
  const int steps = 4000;
  const double end = 0.8 * kTc;
  for (int k = 1; k <= steps; ++k) {
    const double t = end * k / steps;
    point.uniaxialStep(kSigma, t);
    if (k % 1000 != 0) continue;
    const double D = damageAt(t), p = pAt(t);
    EXPECT_NEAR(point.variables[8], D, 2e-3 * D) << t;          // ENDO
    EXPECT_NEAR(point.variables[6], p, 2e-3 * p) << t;          // EPSPEQ
    EXPECT_NEAR(point.variables[0], p, 2e-3 * p) << t;          // EPSPXX
    EXPECT_NEAR(point.variables[1], -p / 2, 1e-3 * p) << t;     // EPSPYY
    EXPECT_NEAR(point.variables[2], -p / 2, 1e-3 * p) << t;     // EPSPZZ (the hoop direction)
    EXPECT_NEAR(point.variables[7], rAt(t), 2e-3 * rAt(t)) << t;  // ECROISOT
    const double elastic = kSigma / ((1 - point.variables[8]) * kE);
    EXPECT_NEAR(point.strain[0], elastic + point.variables[6], 1e-12) << t;
    EXPECT_NEAR(point.strain[1], -kNu * elastic - point.variables[6] / 2, 1e-12) << t;
    EXPECT_NEAR(point.strain[0], kSigma / ((1 - D) * kE) + p, 2e-3 * point.strain[0]) << t;
  }
}

TEST(ViscEndoLemaitre, ImplicitEulerIsFirstOrderInTheStep) {
  const double exact = damageAt(0.8 * kTc);
  const double e1 = std::fabs(damageWithSteps(100) - exact);
  const double e2 = std::fabs(damageWithSteps(200) - exact);
  const double e3 = std::fabs(damageWithSteps(400) - exact);
  EXPECT_NEAR(e1 / e2, 2.0, 0.1);
  EXPECT_NEAR(e2 / e3, 2.0, 0.05);
  EXPECT_LT(e3, 1e-2 * exact);
}

TEST(ViscEndoLemaitre, CarriesTheStressUntilRuptureThenBreaks) {
  const auto law = lawOf(kN, 1 / kK, 0, 0, kR, kA);
  Point point(law);
  point.uniaxialStep(kSigma, 0.0);
  const double dt = kTc / 2000;
  // Under a constant stress the damage decouples: the implicit step solves
  //   h(D) = (D - D_n)(1 - D)^R - dt (sigma / A_D)^R = 0,
  // whose smaller root lies in [D_n, D*], D* = (1 + R D_n)/(R + 1) where h is largest; when
  // h(D*) < 0 no damage carries sigma at the step's end.
  auto implicitDamage = [&](double Dn) {
    auto h = [&](double D) { return (D - Dn) * std::pow(1 - D, kR) - dt * std::pow(kSigma / kA, kR); };
    double lo = Dn, hi = (1 + kR * Dn) / (kR + 1);
    if (h(hi) < 0) return -1.0;
    for (int i = 0; i < 200; ++i) (h(0.5 * (lo + hi)) < 0 ? lo : hi) = 0.5 * (lo + hi);
    return 0.5 * (lo + hi);
  };
  double expected = 0;
  int k = 1;
  for (; k <= 2100; ++k) {
    expected = implicitDamage(expected);
    const bool carried = point.tryUniaxialStep(kSigma, k * dt);
    ASSERT_EQ(carried, expected >= 0) << "step " << k;
    if (!carried) break;
    ASSERT_NEAR(point.variables[8], expected, 1e-9) << "step " << k;
  }
  // The implicit steps carry sigma until a few steps before t_c (t_99 = t_c (1 - 1e-6) here).
  const double last = point.time;
  EXPECT_LT(last, kTc);
  EXPECT_GT(last, kTc - 5 * dt);
  EXPECT_LT(point.variables[8], ViscEndoLemaitre::kDamageMax);

  // A larger strain over a long step: D would pass 0.99, so the point breaks (code_aster's
  // DAMMAX): D = 0.99, no flow in the step, the stress 1% of the effective trial stress.
  const double e[4] = {2 * point.strain[0], point.strain[1], point.strain[2], 0};
  std::vector<double> v;
  const auto out = point.at(e, last + kTc, v);
  EXPECT_EQ(v[8], 0.99);
  EXPECT_EQ(v[6], point.variables[6]);
  EXPECT_EQ(v[7], point.variables[7]);
  EXPECT_EQ(v[9], 0.0);
  const double lambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu)), mu = kE / (2 * (1 + kNu));
  const double de = e[0] - point.strain[0];
  const double trialXX = point.stress[0] / (1 - point.variables[8]) + (lambda + 2 * mu) * de;
  const double trialYY = point.stress[1] / (1 - point.variables[8]) + lambda * de;
  EXPECT_NEAR(out.stress(0, 0), 0.01 * trialXX, 1e-9 * trialXX);
  EXPECT_NEAR(out.stress(1, 1), 0.01 * trialYY, 1e-9 * trialXX);
  // Broken, it stays so: the next step neither flows nor heals.
  point.accept(e, last + kTc, out, v);
  point.at(e, last + 2 * kTc, v);
  EXPECT_EQ(v[8], 0.99);
  EXPECT_EQ(v[6], point.variables[6]);
}

TEST(ViscEndoLemaitre, StrainHardeningAndThresholdWithoutDamage) {
  const double n = 4, oneOverM = 0.2, sy = 50, sigma = 200;
  const auto law = lawOf(n, 1 / kK, oneOverM, sy, kR, 1e12);
  Point point(law);
  point.uniaxialStep(sigma, 0.0);
  const int steps = 2000;
  const double end = 100;
  const double rate = std::pow((sigma - sy) / kK, n), exponent = 1 + n * oneOverM;
  for (int k = 1; k <= steps; ++k) point.uniaxialStep(sigma, end * k / steps);
  const double r = std::pow(exponent * rate * end, 1 / exponent);
  EXPECT_NEAR(point.variables[7], r, 2e-3 * r);
  EXPECT_NEAR(point.variables[6], r, 2e-3 * r);  // p = r without damage
  EXPECT_LT(point.variables[8], 1e-15);
}

TEST(ViscEndoLemaitre, ConstantRateWithoutDamageNorHardeningIsExact) {
  const double sy = 50, sigma = 200;
  const auto law = lawOf(kN, 1 / kK, 0, sy, kR, 1e12);
  Point point(law);
  point.uniaxialStep(sigma, 0.0);
  for (int k = 1; k <= 5; ++k) point.uniaxialStep(sigma, 7.0 * k);
  const double p = std::pow((sigma - sy) / kK, kN) * 35.0;
  EXPECT_NEAR(point.variables[6], p, 1e-10 * p);
  EXPECT_NEAR(point.strain[0], sigma / kE + p, 1e-10 * p);
}

TEST(ViscEndoLemaitre, BelowTheThresholdNothingFlows) {
  const auto law = lawOf(kN, 1 / kK, 0, 250, kR, kA);
  Point point(law);
  point.uniaxialStep(kSigma, 0.0);
  point.uniaxialStep(kSigma, 100.0);
  for (double v : point.variables) EXPECT_EQ(v, 0.0);
  EXPECT_NEAR(point.strain[0], kSigma / kE, 1e-15);
}

namespace {

// The tangent against central differences of the stress, from an accepted state with
// damage and flow, for an increment e - e_n over dt.
void checkTangent(PlaneHypothesis h, const double e[4], double dt, double sy) {
  const auto law = lawOf(kN, 1 / kK, 0.2, sy, kR, kA, h);
  Point point(law);
  // A history: loading then creep, so that D, r and the stress are not zero.
  const double e0[4] = {1.2e-3, -0.3e-3, h == PlaneHypothesis::PlaneStrain ? 0.0 : 0.2e-3, 0.5e-3};
  std::vector<double> v;
  auto out = point.at(e0, 0.0, v);
  point.accept(e0, 0.0, out, v);
  out = point.at(e0, 1.0, v);
  point.accept(e0, 1.0, out, v);
  ASSERT_GT(point.variables[8], 0);
  if (sy < 100) {
    ASSERT_GT(point.variables[7], 0);
  }

  out = point.at(e, 1.0 + dt, v);
  const VoigtTangent T = out.tangent;
  const double h0 = 1e-8;
  const bool planeStrain = h == PlaneHypothesis::PlaneStrain;
  for (int j = 0; j < 4; ++j) {
    if (planeStrain && j == kZZ) continue;  // no zz strain in D_PLAN
    double ep[4], em[4];
    for (int i = 0; i < 4; ++i) ep[i] = em[i] = e[i];
    const double step = j == kXY ? h0 / 2 : h0;  // Voigt's 2 e12
    ep[j] += step;
    em[j] -= step;
    std::vector<double> vp, vm;
    double sp[4], sm[4];
    Point::stressOf(point.at(ep, 1.0 + dt, vp), sp);
    Point::stressOf(point.at(em, 1.0 + dt, vm), sm);
    for (int i = 0; i < 4; ++i) {
      const double fd = (sp[i] - sm[i]) / (2 * h0);
      EXPECT_NEAR(T(i, j), fd, 1e-5 * T.cwiseAbs().maxCoeff()) << "(" << i << ", " << j << ")";
    }
  }
}

}  // namespace

TEST(ViscEndoLemaitre, ConsistentTangentAgainstFiniteDifferencesInPlaneStrain) {
  const double e[4] = {1.5e-3, -0.2e-3, 0.0, 0.7e-3};
  checkTangent(PlaneHypothesis::PlaneStrain, e, 0.5, 0.0);
  checkTangent(PlaneHypothesis::PlaneStrain, e, 2.0, 30.0);
  const double unloading[4] = {0.9e-3, -0.4e-3, 0.0, 0.3e-3};
  checkTangent(PlaneHypothesis::PlaneStrain, unloading, 0.1, 30.0);
}

TEST(ViscEndoLemaitre, ConsistentTangentAgainstFiniteDifferencesInAxis) {
  const double e[4] = {1.4e-3, -0.5e-3, 0.6e-3, 0.4e-3};
  checkTangent(PlaneHypothesis::Axisymmetric, e, 0.5, 0.0);
  checkTangent(PlaneHypothesis::Axisymmetric, e, 3.0, 40.0);
  const double hydrostatic[4] = {2.0e-3, 1.8e-3, 1.9e-3, 0.05e-3};  // mostly mean strain: dD/dq couples it
  checkTangent(PlaneHypothesis::Axisymmetric, hydrostatic, 1.0, 0.0);
  // No time: elastic with the damaged stiffness (1 - D) E.
  checkTangent(PlaneHypothesis::Axisymmetric, e, 0.0, 0.0);
}

TEST(ViscEndoLemaitre, RefusesPlaneStressAndBadParameters) {
  const auto p = viscEndoLemaitreParameters(kE, kNu, kN, 1 / kK, 0, 0, kR, kA);
  EXPECT_THROW(ViscEndoLemaitre(p, PlaneHypothesis::PlaneStress), Error);
  auto message = [](auto f) {
    try {
      f();
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message([] { viscEndoLemaitreParameters(kE, kNu, 0, 1 / kK, 0, 0, kR, kA); }).find("LEMAITRE's N"),
            std::string::npos);
  EXPECT_NE(message([] { viscEndoLemaitreParameters(kE, kNu, kN, 0, 0, 0, kR, kA); }).find("UN_SUR_K"),
            std::string::npos);
  EXPECT_NE(message([] { viscEndoLemaitreParameters(kE, kNu, kN, 1 / kK, -1, 0, kR, kA); }).find("UN_SUR_M"),
            std::string::npos);
  EXPECT_NE(message([] { viscEndoLemaitreParameters(kE, kNu, kN, 1 / kK, 0, -1, kR, kA); }).find("VISC_ENDO's SY"),
            std::string::npos);
  EXPECT_NE(message([] { viscEndoLemaitreParameters(kE, kNu, kN, 1 / kK, 0, 0, -1, kA); }).find("R_D"),
            std::string::npos);
  EXPECT_NE(message([] { viscEndoLemaitreParameters(kE, kNu, kN, 1 / kK, 0, 0, kR, 0); }).find("A_D"),
            std::string::npos);
}
