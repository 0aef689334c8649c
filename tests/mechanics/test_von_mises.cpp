// The von Mises laws at one material point, against closed forms derived by hand:
// uniaxial stress (C_PLAN: s_yy = s_zz = 0; AXIS: along the axis, s_rr = s_tt = 0)
// loaded into the plastic range and reversed (Bauschinger), pure shear in D_PLAN;
// the consistent tangent against central finite differences of the stress; and
// the plane stress condition s_zz = 0.
//
// Uniaxial closed forms with E, the hardening slope H = E E_T / (E - E_T), SY:
// loading past eps_y = SY/E follows sigma = SY + E_T (eps - eps_y) for every
// hardening kind (the curve is the uniaxial response), with p = (sigma - SY)/H.
// Reversing from sigma_1 (p_1), the law yields again at
//   isotropic:  sigma = -sigma_1                  (R grew to sigma_1)
//   kinematic:  sigma = sigma_1 - 2 SY            (the elastic range 2 SY moved)
//   mixed:      sigma = alpha_1 - R(p_1), alpha_1 = 1.5 C p_1, R(p) = SY + (H - 1.5 C) p
// and then follows the slope E_T again. XCINXX = 2/3 alpha with alpha = 1.5 C eps_p.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/error.hpp"
#include "../support/material_point.hpp"
#include "mechanics/isotropic_hardening.hpp"
#include "mechanics/von_mises_plasticity.hpp"

using namespace aster;
using namespace aster::mechanics;

namespace {

constexpr double kE = 200e3, kNu = 0.3, kSy = 200, kEt = 20e3;
constexpr double kH = kE * kEt / (kE - kEt);

using Point = test_support::MaterialPoint;

// C_PLAN, uniaxial stress along x: e_xx given, e_yy such that s_yy = 0 (the law
// itself makes s_zz = 0). Returns the accepted s_xx.
double uniaxialPlaneStress(Point& point, double exx) {
  Eigen::Matrix2d e = point.strain;
  e(0, 0) = exx;
  std::vector<double> v;
  LawOutput<VoigtTangent> out;
  for (int it = 0; it < 50; ++it) {
    out = point.at(e, 0, v);
    if (std::fabs(out.stress(1, 1)) <= 1e-13 * std::fabs(out.stress(0, 0))) break;
    e(1, 1) -= out.stress(1, 1) / out.tangent(kYY, kYY);
  }
  EXPECT_LE(std::fabs(out.stress(1, 1)), 1e-12 * std::fabs(out.stress(0, 0)));
  point.accept(e, out.strainZZ, out, v);
  return out.stress(0, 0);
}

// AXIS, uniaxial stress along the axis y: e_yy given, e_rr = e_tt (symmetry)
// such that s_rr = s_tt = 0. Returns the accepted s_yy.
double uniaxialAxial(Point& point, double eyy) {
  Eigen::Matrix2d e = point.strain;
  e(1, 1) = eyy;
  double ett = point.strainZZ;
  std::vector<double> v;
  LawOutput<VoigtTangent> out;
  for (int it = 0; it < 50; ++it) {
    out = point.at(e, ett, v);
    if (std::fabs(out.stress(0, 0)) <= 1e-13 * std::fabs(out.stress(1, 1))) break;
    const double d = -out.stress(0, 0) / (out.tangent(kXX, kXX) + out.tangent(kXX, kZZ));
    e(0, 0) += d;
    ett += d;
  }
  EXPECT_LE(std::fabs(out.stress(0, 0)), 1e-12 * std::fabs(out.stress(1, 1)));
  EXPECT_NEAR(out.stressZZ, out.stress(0, 0), 1e-9 * std::fabs(out.stress(1, 1)));
  point.accept(e, ett, out, v);
  return out.stress(1, 1);
}

struct Expected {
  double stress, p, plasticStrain;
};

// Load to +0.01, reverse to -0.01 in one step, check the closed form.
void checkBauschinger(const VonMisesParameters& parameters, PlaneHypothesis hypothesis, const Expected& loaded,
                      const Expected& reversed, double xcinLoaded, double xcinReversed) {
  // The plane stress return of the isotropic laws holds the yield condition to
  // RESI_INTE_RELA x SY (code_aster's): asked to near rounding here.
  VonMisesParameters tight = parameters;
  tight.tolerance = 1e-13;
  const VonMisesPlasticity law(tight, hypothesis);
  Point point(law);
  auto uniaxial = [&](double e) {
    return hypothesis == PlaneHypothesis::PlaneStress ? uniaxialPlaneStress(point, e) : uniaxialAxial(point, e);
  };
  const int axis = hypothesis == PlaneHypothesis::PlaneStress ? 0 : 1;
  const auto names = law.internalVariableNames();
  auto variable = [&](const char* name) {
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == name) return point.variables[i];
    ADD_FAILURE() << "no variable " << name;
    return 0.0;
  };
  const double tol = 1e-10;
  for (const auto& [strain, expected, xcin] : {std::tuple{0.01, loaded, xcinLoaded}, {-0.01, reversed, xcinReversed}}) {
    const double sigma = uniaxial(strain);
    EXPECT_NEAR(sigma, expected.stress, tol * std::fabs(expected.stress)) << "at strain " << strain;
    EXPECT_NEAR(variable("EPSPEQ"), expected.p, tol * expected.p) << "at strain " << strain;
    EXPECT_EQ(variable("INDIPLAS"), 1.0);
    // The plastic strain along the load: total minus elastic.
    EXPECT_NEAR(point.strain(axis, axis) - sigma / parameters.young, expected.plasticStrain,
                tol * std::fabs(expected.plasticStrain));
    if (parameters.variables != VonMisesVariables::Isotropic) {
      const char* component = axis == 0 ? "XCINXX" : "XCINYY";
      EXPECT_NEAR(variable(component), xcin, tol * std::fabs(xcin)) << component << " at strain " << strain;
    }
  }
  // Elastic unloading by 1e-4: the stress drops by E 1e-4, nothing plastic.
  const double before = point.stress[axis == 0 ? 0 : 1];
  const double p = variable("EPSPEQ");
  const double sigma = uniaxial(-0.01 + 1e-4);
  EXPECT_NEAR(sigma - before, kE * 1e-4, 1e-9 * kE * 1e-4);
  EXPECT_EQ(variable("INDIPLAS"), 0.0);
  EXPECT_EQ(variable("EPSPEQ"), p);
}

// Loading to 0.01: sigma = SY + E_T (0.01 - SY/E) = 380, p = 180/H, eps_p = 0.01 - 380/E.
constexpr double kLoaded = kSy + kEt * (0.01 - kSy / kE);
const Expected kLoadedState{kLoaded, (kLoaded - kSy) / kH, 0.01 - kLoaded / kE};

TEST(VonMises, IsotropicLinearBauschinger) {
  // Reverse yield at -380 when eps = eps_p1 - 380/E, then slope E_T.
  const double yieldAt = kLoadedState.plasticStrain - kLoaded / kE;
  const double sigma = -kLoaded + kEt * (-0.01 - yieldAt);
  const Expected reversed{sigma, kLoadedState.p + (-kLoaded - sigma) / kH, -0.01 - sigma / kE};
  for (auto hypothesis : {PlaneHypothesis::PlaneStress, PlaneHypothesis::Axisymmetric})
    checkBauschinger(isotropicLinearParameters(kE, kNu, kEt, kSy), hypothesis, kLoadedState, reversed, 0, 0);
}

TEST(VonMises, KinematicLinearBauschinger) {
  // Reverse yield at 380 - 2 SY, then slope E_T; p accumulates |d eps_p|.
  const double yieldStress = kLoaded - 2 * kSy;
  const double yieldAt = kLoadedState.plasticStrain + yieldStress / kE;
  const double sigma = yieldStress + kEt * (-0.01 - yieldAt);
  const double epsP = -0.01 - sigma / kE;
  const Expected reversed{sigma, kLoadedState.p + (kLoadedState.plasticStrain - epsP), epsP};
  // alpha = H eps_p (C = 2/3 H), XCINXX = 2/3 alpha.
  for (auto hypothesis : {PlaneHypothesis::PlaneStress, PlaneHypothesis::Axisymmetric})
    checkBauschinger(kinematicLinearParameters(kE, kNu, kEt, kSy), hypothesis, kLoadedState, reversed,
                     2.0 / 3.0 * kH * kLoadedState.plasticStrain, 2.0 / 3.0 * kH * epsP);
}

TEST(VonMises, MixedLinearBauschinger) {
  // Half of H kinematic: 1.5 C = H/2, R(p) = SY + H/2 p, alpha = H/2 eps_p.
  const double C = kH / 3.0;
  const double alpha1 = 1.5 * C * kLoadedState.p;
  const double yieldStress = alpha1 - (kSy + (kH - 1.5 * C) * kLoadedState.p);
  const double yieldAt = kLoadedState.plasticStrain + yieldStress / kE;
  const double sigma = yieldStress + kEt * (-0.01 - yieldAt);
  const double epsP = -0.01 - sigma / kE;
  const Expected reversed{sigma, kLoadedState.p + (kLoadedState.plasticStrain - epsP), epsP};
  for (auto hypothesis : {PlaneHypothesis::PlaneStress, PlaneHypothesis::Axisymmetric})
    checkBauschinger(mixedLinearParameters(kE, kNu, kEt, kSy, C), hypothesis, kLoadedState, reversed,
                     C * kLoadedState.plasticStrain, C * epsP);
}

// A traction curve of three segments; the curve is the uniaxial response, so
// (eps, sigma) on it is reached exactly, within any segment, in one step.
TractionCurve threeSegments(IsotropicHardening::Beyond beyond) {
  TractionCurve c;
  c.strain = {0.001, 0.004, 0.01, 0.02};  // E = 200e3 from the first point
  c.stress = {200, 320, 400, 450};
  c.beyond = beyond;
  return c;
}

TEST(VonMises, IsotropicTractionCurveIsTheUniaxialResponse) {
  const TractionCurve curve = threeSegments(IsotropicHardening::Beyond::Linear);
  for (auto hypothesis : {PlaneHypothesis::PlaneStress, PlaneHypothesis::Axisymmetric}) {
    VonMisesParameters parameters = isotropicTractionParameters(kNu, curve);
    parameters.tolerance = 1e-13;  // the plane stress return to rounding (see checkBauschinger)
    const VonMisesPlasticity law(parameters, hypothesis);
    EXPECT_DOUBLE_EQ(law.parameters().young, 200e3);
    Point point(law);
    auto uniaxial = [&](double e) {
      return hypothesis == PlaneHypothesis::PlaneStress ? uniaxialPlaneStress(point, e) : uniaxialAxial(point, e);
    };
    // Interpolated points of each segment, and one past the end (linear extension).
    for (double e : {0.0025, 0.004, 0.007, 0.015, 0.03}) {
      double sigma = 0;
      if (e <= 0.004) sigma = 200 + (e - 0.001) * 120 / 0.003;
      else if (e <= 0.01) sigma = 320 + (e - 0.004) * 80 / 0.006;
      else sigma = 400 + (e - 0.01) * 50 / 0.01;
      EXPECT_NEAR(uniaxial(e), sigma, 1e-10 * sigma) << "eps = " << e;
      EXPECT_NEAR(point.variables[0], e - sigma / 200e3, 1e-10 * e);
    }
  }
}

TEST(VonMises, MixedTractionKeepsTheCurveAndMovesTheCentre) {
  // VMIS_ECMI_TRAC: monotonic loading follows the curve whatever C; the reverse
  // yield is alpha_1 - R(p_1) with R the curve less 1.5 C p.
  const TractionCurve curve = threeSegments(IsotropicHardening::Beyond::Constant);
  const double C = 10e3;
  const VonMisesPlasticity law(mixedTractionParameters(kNu, curve, C), PlaneHypothesis::PlaneStress);
  Point point(law);
  const double sigma1 = uniaxialPlaneStress(point, 0.007);
  EXPECT_NEAR(sigma1, 360, 1e-10 * 360);
  const double p1 = 0.007 - 360 / 200e3;
  EXPECT_NEAR(point.variables[0], p1, 1e-12);
  EXPECT_NEAR(point.variables[2], C * p1, 1e-9);  // XCINXX = C eps_p
  // Elastic down to just above the reverse yield stress 1.5 C p1 - (360 - 1.5 C p1).
  const double reverseYield = 3 * C * p1 - 360;
  const double eps = 0.007 + (reverseYield + 1.0 - 360) / 200e3;
  EXPECT_NEAR(uniaxialPlaneStress(point, eps), reverseYield + 1.0, 1e-9 * 360);
  EXPECT_EQ(point.variables[1], 0.0);
  uniaxialPlaneStress(point, eps - 2.0 / 200e3);
  EXPECT_EQ(point.variables[1], 1.0);
}

TEST(VonMises, PureShearInPlaneStrain) {
  // D_PLAN, e_xy = gamma/2 only: the stress stays pure shear, tau = R(p)/sqrt(3)
  // with gamma = tau/mu + sqrt(3) p. Linear R: p = (gamma - SY/(sqrt3 mu)) / (sqrt3 + H/(sqrt3 mu)).
  const VonMisesPlasticity law(isotropicLinearParameters(kE, kNu, kEt, kSy), PlaneHypothesis::PlaneStrain);
  const double mu = kE / (2 * (1 + kNu)), s3 = std::sqrt(3.0);
  Point point(law);
  for (double gamma : {0.001, 0.02}) {
    Eigen::Matrix2d e;
    e << 0, gamma / 2, gamma / 2, 0;
    std::vector<double> v;
    const auto out = point.at(e, 0, v);
    const double p = std::max(0.0, (gamma - kSy / (s3 * mu)) / (s3 + kH / (s3 * mu)));
    const double tau = p > 0 ? (kSy + kH * p) / s3 : mu * gamma;
    EXPECT_NEAR(out.stress(0, 1), tau, 1e-10 * tau);
    EXPECT_NEAR(out.stress(0, 0), 0, 1e-10 * tau);
    EXPECT_NEAR(out.stressZZ, 0, 1e-10 * tau);
    EXPECT_NEAR(v[0], p, 1e-10 * std::max(p, 1e-6));
    point.accept(e, 0, out, v);
  }
}

// Every law and hypothesis: after a plastic history, the tangent of a further
// (plastic) increment against central differences of the stress.
TEST(VonMises, ConsistentTangentMatchesFiniteDifferences) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-1, 1);
  const TractionCurve curve = threeSegments(IsotropicHardening::Beyond::Linear);
  const std::vector<VonMisesParameters> laws = {
      isotropicLinearParameters(kE, kNu, kEt, kSy), kinematicLinearParameters(kE, kNu, kEt, kSy),
      mixedLinearParameters(kE, kNu, kEt, kSy, kH / 3), isotropicTractionParameters(kNu, curve),
      mixedTractionParameters(kNu, curve, 5e3)};
  for (VonMisesParameters parameters : laws)
    for (auto hypothesis : {PlaneHypothesis::PlaneStrain, PlaneHypothesis::PlaneStress, PlaneHypothesis::Axisymmetric}) {
      parameters.tolerance = 1e-13;  // the derivative of the exact return (see checkBauschinger)
      const VonMisesPlasticity law(parameters, hypothesis);
      Point point(law);
      // A plastic history: two non-proportional steps.
      for (int step = 0; step < 2; ++step) {
        Eigen::Matrix2d e = point.strain;
        e(0, 0) += 0.004 + 0.001 * u(random);
        e(1, 1) += 0.002 * u(random);
        e(0, 1) = e(1, 0) = e(0, 1) + 0.002 * u(random);
        const double ezz = hypothesis == PlaneHypothesis::Axisymmetric ? point.strainZZ + 0.001 * u(random) : 0.0;
        std::vector<double> v;
        const auto out = point.at(e, ezz, v);
        point.accept(e, ezz, out, v);
      }
      // A further plastic increment, and its derivative.
      Eigen::Matrix2d e = point.strain;
      e(0, 0) += 0.003;
      e(0, 1) = e(1, 0) = e(0, 1) - 0.001;
      const double ezz = hypothesis == PlaneHypothesis::Axisymmetric ? point.strainZZ - 0.0005 : 0.0;
      std::vector<double> v;
      const auto out = point.at(e, ezz, v);
      ASSERT_EQ(v[parameters.variables == VonMisesVariables::Kinematic ? 6 : 1], 1.0);
      const double h = 1e-8;
      const int columns = hypothesis == PlaneHypothesis::Axisymmetric ? 4 : 3;
      const int component[4] = {kXX, kYY, kXY, kZZ};
      for (int c = 0; c < columns; ++c) {
        auto stressAt = [&](double delta) {
          Eigen::Matrix2d ee = e;
          double zz = ezz;
          switch (component[c]) {
            case kXX: ee(0, 0) += delta; break;
            case kYY: ee(1, 1) += delta; break;
            case kXY: ee(0, 1) += delta / 2; ee(1, 0) += delta / 2; break;  // 2 e12 is the Voigt strain
            default: zz += delta;
          }
          std::vector<double> w;
          const auto o = point.at(ee, zz, w);
          return Eigen::Vector4d(o.stress(0, 0), o.stress(1, 1), o.stressZZ, o.stress(0, 1));
        };
        const Eigen::Vector4d fd = (stressAt(h) - stressAt(-h)) / (2 * h);
        for (int r : {kXX, kYY, kZZ, kXY}) {
          if (hypothesis == PlaneHypothesis::PlaneStress && r == kZZ) continue;
          EXPECT_NEAR(out.tangent(r, component[c]), fd(r), 1e-5 * kE)
              << "row " << r << " column " << component[c] << " hypothesis " << planeHypothesisName(hypothesis);
        }
      }
      // Symmetric, as the element requires.
      EXPECT_LE((out.tangent - out.tangent.transpose()).norm(), 1e-9 * out.tangent.norm());
    }
}

TEST(VonMises, PlaneStressZeroStressZZ) {
  const VonMisesPlasticity law(mixedLinearParameters(kE, kNu, kEt, kSy, kH / 3), PlaneHypothesis::PlaneStress);
  Point point(law);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int step = 0; step < 20; ++step) {
    Eigen::Matrix2d e = point.strain;
    e(0, 0) += 0.003 * u(random);
    e(1, 1) += 0.003 * u(random);
    e(0, 1) = e(1, 0) = e(0, 1) + 0.003 * u(random);
    std::vector<double> v;
    const auto out = point.at(e, 0, v);
    EXPECT_LE(std::fabs(out.stressZZ), 1e-12 * out.stress.norm()) << "step " << step;
    // The zz strain reported is the total one: elastic (from the stress) plus plastic (deviatoric).
    const double elasticZZ = -kNu / kE * out.stress.trace();
    const double plasticTrace = (e.trace() - (1 - kNu) / kE * out.stress.trace());
    EXPECT_NEAR(out.strainZZ, elasticZZ - plasticTrace, 1e-12);
    point.accept(e, out.strainZZ, out, v);
  }
}

// The isotropic laws in plane stress, as code_aster integrates them: s_zz = 0 to rounding
// whatever the tolerance, the yield condition to RESI_INTE_RELA x SY (1e-6 by default),
// and a tighter RESI_INTE_RELA gives the return to rounding.
TEST(VonMises, PlaneStressIsotropicReturnHoldsYieldToResiInteRela) {
  for (double tolerance : {1e-6, 1e-3, 1e-15}) {
    VonMisesParameters parameters = isotropicLinearParameters(kE, kNu, kEt, kSy);
    parameters.tolerance = tolerance;
    const VonMisesPlasticity law(parameters, PlaneHypothesis::PlaneStress);
    Point point(law);
    std::mt19937 random(5);
    std::uniform_real_distribution<double> u(-1, 1);
    int plasticSteps = 0;
    for (int step = 0; step < 20; ++step) {
      Eigen::Matrix2d e = point.strain;
      e(0, 0) += 0.003 * u(random);
      e(1, 1) += 0.003 * u(random);
      e(0, 1) = e(1, 0) = e(0, 1) + 0.003 * u(random);
      std::vector<double> v;
      const auto out = point.at(e, 0, v);
      EXPECT_LE(std::fabs(out.stressZZ), 1e-12 * out.stress.norm()) << "step " << step;
      if (v[1] == 1.0) {
        ++plasticSteps;
        const Eigen::Matrix2d s = out.stress - out.stress.trace() / 3 * Eigen::Matrix2d::Identity();
        const double szz = -out.stress.trace() / 3;
        const double q = std::sqrt(1.5 * (s.squaredNorm() + szz * szz));
        const double R = kSy + kH * v[0];
        EXPECT_LE(std::fabs(q - R), std::max(tolerance * kSy, 1e-13 * R)) << "step " << step;
      }
      point.accept(e, out.strainZZ, out, v);
    }
    EXPECT_GT(plasticSteps, 5);
  }
}

TEST(IsotropicHardening, TractionCurveConversionAndReturn) {
  double young = 0;
  const auto h = IsotropicHardening::fromTractionCurve({0.002, 0.0045}, {400, 500},
                                                       IsotropicHardening::Beyond::Refuse, young);
  EXPECT_DOUBLE_EQ(young, 200e3);
  EXPECT_DOUBLE_EQ(h.yield(), 400);
  // p_1 = 0.0045 - 500/200e3 = 0.002: slope 100 / 0.002 = 5e4.
  EXPECT_NEAR(h.value(0.001), 450, 1e-9);
  EXPECT_NEAR(h.slope(0.001), 5e4, 1e-6);
  // q - h dp = R(dp): 1000 - 3e5 dp = 400 + 5e4 dp -> dp = 600 / 3.5e5.
  EXPECT_NEAR(h.returnIncrement(1000, 3e5, 0), 600 / 3.5e5, 1e-15);
  // Past the end of an EXCLU curve.
  EXPECT_THROW(h.returnIncrement(2000, 3e5, 0), Error);
  // A segment steeper than E: p would decrease.
  EXPECT_THROW(IsotropicHardening::fromTractionCurve({0.002, 0.003}, {400, 700}, IsotropicHardening::Beyond::Linear,
                                                     young),
               Error);
  // Mixed: less 1.5 C p.
  EXPECT_NEAR(h.lessKinematic(1e4).value(0.001), 450 - 15, 1e-9);
}

TEST(VonMises, RefusesBadParameters) {
  EXPECT_THROW(isotropicLinearParameters(kE, kNu, kE, kSy), Error);        // E_T >= E
  EXPECT_THROW(kinematicLinearParameters(kE, kNu, 0, kSy), Error);         // no kinematic modulus
  EXPECT_THROW(VonMisesPlasticity(isotropicLinearParameters(kE, 0.5, kEt, kSy), PlaneHypothesis::PlaneStrain), Error);
  EXPECT_THROW(VonMisesPlasticity(isotropicLinearParameters(kE, kNu, kEt, 0), PlaneHypothesis::PlaneStrain), Error);
}

}  // namespace
