// VISC_DRUC_PRAG at one material point, against references computed here
// independently of the law's code:
//  - the hardening functions alpha, R, beta at their nodes and in between (hand values);
//  - the elastic domain: a trial state with q + alpha I1 - R <= 0 is elastic (Hooke);
//  - one viscoplastic step satisfies the implicit Euler equations of the model,
//    evaluated on the law's own output: sigma = sigma_trial - dp D:(3/2 s/q + beta 1)
//    and dp = A dt <(q + alpha(p) I1 - R(p)) / PREF>^N at the end of the step;
//  - a strain path of many small steps follows a fine explicit (RK4) integration
//    of the rate equations, written here from the model's definition, with the
//    first-order error of the implicit scheme (halving the step halves it);
//  - the tangent against central finite differences of the stress (elastic,
//    viscoplastic before and after the peak, past the ultimate threshold; AXIS and
//    D_PLAN), and the tangent integrate() returns is its symmetric part.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "mechanics/visc_drucker_prager.hpp"

using namespace aster;
using namespace aster::mechanics;

namespace {

// ssnv211a's rock.
constexpr double kE = 5000e6, kNu = 0.12;
const double kMu = kE / (2 * (1 + kNu)), kK = kE / (3 * (1 - 2 * kNu));

ViscDruckerPragerMaterial rock() {
  ViscDruckerPragerMaterial m;
  m.pref = 0.1e6;
  m.a = 1.5e-12;
  m.n = 4.5;
  m.pPeak = 0.015;
  m.pUlt = 0.028;
  m.alpha0 = 0.065;
  m.alphaPeak = 0.26;
  m.alphaUlt = 0.091;
  m.r0 = 1.3021e6;
  m.rPeak = 6.24808e6;
  m.rUlt = 1.30808e6;
  m.beta0 = -0.15;
  m.betaPeak = 0.0;
  m.betaUlt = 0.13;
  return m;
}

ViscDruckerPrager lawOf(PlaneHypothesis h, double tolerance = 1e-12) {
  ViscDruckerPragerParameters p;
  p.young = kE;
  p.poisson = kNu;
  p.material = rock();
  p.tolerance = tolerance;
  p.maxIterations = 100;
  return ViscDruckerPrager(p, h);
}

using Vec4 = std::array<double, 4>;  // tensor components xx, yy, zz, xy

struct Result {
  Vec4 stress;
  std::vector<double> variables;
  VoigtTangent tangent;
};

LawInput inputOf(const Vec4& sn, const std::vector<double>& vn, const Vec4& de, double dt) {
  LawInput in;
  in.strain << de[0], de[3], de[3], de[1];
  in.strainZZ = de[2];
  in.strainIncrement = in.strain;
  in.strainIncrementZZ = de[2];
  in.previousStress = sn.data();
  in.previousVariables = vn.data();
  in.time = dt;
  in.timeIncrement = dt;
  return in;
}

Result step(const ViscDruckerPrager& law, const Vec4& sn, const std::vector<double>& vn, const Vec4& de, double dt) {
  const LawInput in = inputOf(sn, vn, de, dt);
  Result r;
  r.variables.assign(4, -1.0);
  LawOutput<VoigtTangent> out;
  out.variables = r.variables.data();
  law.integrate(in, out, true);
  r.stress = {out.stress(0, 0), out.stress(1, 1), out.stressZZ, out.stress(0, 1)};
  r.tangent = out.tangent;
  return r;
}

double deviatorContract(const Vec4& s) { return s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + 2 * s[3] * s[3]; }
Vec4 deviator(const Vec4& sig) {
  const double m = (sig[0] + sig[1] + sig[2]) / 3;
  return {sig[0] - m, sig[1] - m, sig[2] - m, sig[3]};
}
double vonMises(const Vec4& sig) { return std::sqrt(1.5 * deviatorContract(deviator(sig))); }
double trace(const Vec4& sig) { return sig[0] + sig[1] + sig[2]; }

// Hooke: sigma = lambda tr(e) 1 + 2 mu e (tensor components).
Vec4 hooke(const Vec4& e) {
  const double lambda = kK - 2 * kMu / 3, tr = e[0] + e[1] + e[2];
  return {lambda * tr + 2 * kMu * e[0], lambda * tr + 2 * kMu * e[1], lambda * tr + 2 * kMu * e[2], 2 * kMu * e[3]};
}

// The hardening functions written from their definition (linear between the nodes).
struct Functions {
  double alpha, r, beta;
};
Functions functionsAt(double p) {
  const ViscDruckerPragerMaterial m = rock();
  auto lerp = [](double a, double b, double t) { return a + (b - a) * t; };
  if (p < m.pPeak) {
    const double t = p / m.pPeak;
    return {lerp(m.alpha0, m.alphaPeak, t), lerp(m.r0, m.rPeak, t), lerp(m.beta0, m.betaPeak, t)};
  }
  if (p < m.pUlt) {
    const double t = (p - m.pPeak) / (m.pUlt - m.pPeak);
    return {lerp(m.alphaPeak, m.alphaUlt, t), lerp(m.rPeak, m.rUlt, t), lerp(m.betaPeak, m.betaUlt, t)};
  }
  return {m.alphaUlt, m.rUlt, m.betaUlt};
}

// A confined, sheared state above the threshold.
const Vec4 kLoaded = {-5e6, -15e6, -5e6, 1e6};

}  // namespace

TEST(ViscDruckerPrager, HardeningFunctionsAtTheirNodes) {
  const ViscDruckerPragerMaterial m = rock();
  const auto at0 = hardeningValues(m, 0), atPeak = hardeningValues(m, 0.015), atUlt = hardeningValues(m, 0.028);
  EXPECT_DOUBLE_EQ(at0.alpha, 0.065);
  EXPECT_DOUBLE_EQ(at0.r, 1.3021e6);
  EXPECT_DOUBLE_EQ(at0.beta, -0.15);
  EXPECT_DOUBLE_EQ(atPeak.alpha, 0.26);
  EXPECT_DOUBLE_EQ(atPeak.r, 6.24808e6);
  EXPECT_DOUBLE_EQ(atPeak.beta, 0.0);
  EXPECT_DOUBLE_EQ(atUlt.alpha, 0.091);
  EXPECT_DOUBLE_EQ(atUlt.r, 1.30808e6);
  EXPECT_DOUBLE_EQ(atUlt.beta, 0.13);
  const auto mid = hardeningValues(m, 0.0215);  // halfway from the peak to the ultimate threshold
  EXPECT_NEAR(mid.alpha, (0.26 + 0.091) / 2, 1e-15);
  EXPECT_NEAR(mid.r, (6.24808e6 + 1.30808e6) / 2, 1e-8);
  EXPECT_NEAR(mid.beta, 0.065, 1e-15);
  const auto beyond = hardeningValues(m, 0.5);
  EXPECT_DOUBLE_EQ(beyond.r, 1.30808e6);
  EXPECT_NEAR(hardeningSlopes(m, 0).r, (6.24808e6 - 1.3021e6) / 0.015, 1e-3);
  EXPECT_NEAR(hardeningSlopes(m, 1).alpha, (0.091 - 0.26) / 0.013, 1e-12);
  EXPECT_EQ(hardeningSlopes(m, 2).beta, 0.0);
  EXPECT_EQ(hardeningPiece(m, 0.0149), 0);
  EXPECT_EQ(hardeningPiece(m, 0.015), 1);
  EXPECT_EQ(hardeningPiece(m, 0.028), 2);
}

TEST(ViscDruckerPrager, InsideTheThresholdTheStepIsElastic) {
  const ViscDruckerPrager law = lawOf(PlaneHypothesis::Axisymmetric);
  // Hydrostatic -5 MPa (ssnv211a's confinement) plus a small deviator: q + alpha I1 - R < 0.
  const Vec4 sn = {-5e6, -5e6, -5e6, 0};
  const std::vector<double> vn = {0.004, 0, 1, 0};
  const Vec4 de = {1e-4, -2e-4, 1e-4, 5e-5};
  const Vec4 trial = hooke(de);
  const Vec4 expected = {sn[0] + trial[0], sn[1] + trial[1], sn[2] + trial[2], trial[3]};
  const Functions f = functionsAt(0.004);
  ASSERT_LT(vonMises(expected) + f.alpha * trace(expected) - f.r, 0);
  const Result r = step(law, sn, vn, de, 100.0);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(r.stress[i], expected[i], 1e-9 * 5e6) << i;
  EXPECT_EQ(r.variables[0], 0.004);  // EPSPEQ kept
  EXPECT_EQ(r.variables[1], 0.0);    // INDIPLAS
  EXPECT_EQ(r.variables[2], 1.0);    // POS: before the peak
  EXPECT_EQ(r.variables[3], 0.0);    // NBITER
  // Hooke's tangent.
  const double lambda = kK - 2 * kMu / 3;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(r.tangent(i, j), lambda + (i == j ? 2 * kMu : 0.0), 1e-6 * kE);
  EXPECT_NEAR(r.tangent(kXY, kXY), kMu, 1e-6 * kE);
}

// One viscoplastic step on each piece: the output satisfies the implicit Euler equations.
TEST(ViscDruckerPrager, OneStepSatisfiesTheImplicitEulerEquations) {
  const ViscDruckerPrager law = lawOf(PlaneHypothesis::Axisymmetric);
  const ViscDruckerPragerMaterial m = rock();
  struct Case {
    double p, dt, pos;
  };
  for (const Case c : {Case{0.002, 100.0, 1}, Case{0.02, 50.0, 2}, Case{0.03, 200.0, 3}}) {
    const std::vector<double> vn = {c.p, 1, c.pos, 3};
    const Vec4 de = {2e-4, -6e-4, 1e-4, 1e-4};
    const Result r = step(law, kLoaded, vn, de, c.dt);
    const double dp = r.variables[0] - c.p;
    ASSERT_GT(dp, 0) << c.p;
    EXPECT_EQ(r.variables[1], 1.0);
    EXPECT_EQ(r.variables[2], c.pos);
    EXPECT_GE(r.variables[3], 1.0);
    ASSERT_EQ(hardeningPiece(m, r.variables[0]), hardeningPiece(m, c.p)) << "the step stays on its piece";
    // Flow at the end state: m = 3/2 s/q + beta 1.
    const Vec4 s = deviator(r.stress);
    const double q = vonMises(r.stress);
    const Functions f = functionsAt(r.variables[0]);
    const Vec4 elastic = hooke(de);
    for (int i = 0; i < 4; ++i) {
      // D:m = 2 mu m_dev + K tr(m) 1 with tr(m) = 3 beta.
      const double Dm = 2 * kMu * 1.5 * s[i] / q + (i < 3 ? 3 * kK * f.beta : 0.0);
      EXPECT_NEAR(r.stress[i], kLoaded[i] + elastic[i] - dp * Dm, 1e-9 * 15e6) << c.p << " " << i;
    }
    // Perzyna at the end state.
    const double criterion = q + f.alpha * trace(r.stress) - f.r;
    const double rate = m.a * std::pow(criterion / m.pref, m.n);
    EXPECT_NEAR(dp, rate * c.dt, 1e-9 * dp) << c.p;
  }
}

// Many steps of the law against a fine RK4 solution of
//   d sigma/dt = D:(eps_dot - p_dot m),  p_dot = A <f / PREF>^N,  m = 3/2 s/q + beta 1.
TEST(ViscDruckerPrager, StrainPathFollowsTheRateEquationsToFirstOrder) {
  const ViscDruckerPrager law = lawOf(PlaneHypothesis::Axisymmetric);
  const ViscDruckerPragerMaterial m = rock();
  const Vec4 rate = {0.25e-5, -1e-5, 0.25e-5, 0.1e-5};  // strain rate (tensor components), per second
  const Vec4 start = {-5e6, -5e6, -5e6, 0};
  const double duration = 2500;  // axial strain 2.5 %: past the peak

  // Reference: RK4 with a step far below the relaxation time.
  using State = std::array<double, 5>;  // stress, p
  auto derivative = [&](const State& y) {
    const Vec4 sig = {y[0], y[1], y[2], y[3]};
    const Functions f = functionsAt(y[4]);
    const double q = vonMises(sig);
    const double crit = q + f.alpha * trace(sig) - f.r;
    const double pdot = crit > 0 ? m.a * std::pow(crit / m.pref, m.n) : 0.0;
    const Vec4 s = deviator(sig);
    Vec4 strainRate = rate;
    for (int i = 0; i < 4; ++i) strainRate[i] -= pdot * (q > 0 ? 1.5 * s[i] / q : 0.0) + (i < 3 ? pdot * f.beta : 0.0);
    const Vec4 sdot = hooke(strainRate);
    return State{sdot[0], sdot[1], sdot[2], sdot[3], pdot};
  };
  State y = {start[0], start[1], start[2], start[3], 0.0};
  const double h = 0.05;
  for (int k = 0; k < static_cast<int>(duration / h + 0.5); ++k) {
    const State k1 = derivative(y);
    State t;
    for (int i = 0; i < 5; ++i) t[i] = y[i] + 0.5 * h * k1[i];
    const State k2 = derivative(t);
    for (int i = 0; i < 5; ++i) t[i] = y[i] + 0.5 * h * k2[i];
    const State k3 = derivative(t);
    for (int i = 0; i < 5; ++i) t[i] = y[i] + h * k3[i];
    const State k4 = derivative(t);
    for (int i = 0; i < 5; ++i) y[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
  }
  ASSERT_GT(y[4], m.pPeak) << "the path passes the peak";

  auto implicitError = [&](int steps) {
    Vec4 sig = start;
    std::vector<double> v = {0, 0, 1, 0};
    const double dt = duration / steps;
    Vec4 de;
    for (int i = 0; i < 4; ++i) de[i] = rate[i] * dt;
    for (int k = 0; k < steps; ++k) {
      const Result r = step(law, sig, v, de, dt);
      sig = r.stress;
      v = r.variables;
    }
    double err = std::fabs(v[0] - y[4]) / y[4];
    for (int i = 0; i < 4; ++i) err = std::max(err, std::fabs(sig[i] - y[i]) / 1e7);
    return err;
  };
  const double coarse = implicitError(2500), fine = implicitError(5000);
  EXPECT_LT(fine, 1e-3);
  EXPECT_GT(coarse / fine, 1.7);  // first order: halving dt halves the error
  EXPECT_LT(coarse / fine, 2.3);
}

TEST(ViscDruckerPrager, TangentMatchesFiniteDifferences) {
  struct Case {
    const char* name;
    Vec4 sn;
    double p, dt;
  };
  const Vec4 confined = {-5e6, -5e6, -5e6, 0};
  const Case cases[] = {{"elastic", confined, 0.0, 10.0},
                        {"before the peak", kLoaded, 0.002, 100.0},
                        {"after the peak", kLoaded, 0.02, 50.0},
                        {"past the ultimate threshold", kLoaded, 0.03, 200.0}};
  for (PlaneHypothesis h : {PlaneHypothesis::Axisymmetric, PlaneHypothesis::PlaneStrain}) {
    const ViscDruckerPrager law = lawOf(h);
    for (const Case& c : cases) {
      const std::vector<double> vn = {c.p, 0, 1, 0};
      Vec4 de = {2e-4, -6e-4, 1e-4, 1e-4};
      if (h == PlaneHypothesis::PlaneStrain) de[2] = 0;
      const VoigtTangent D = law.exactTangent(inputOf(c.sn, vn, de, c.dt));
      const double eps = 1e-8;
      const int columns = 4;
      for (int j = 0; j < columns; ++j) {
        if (h == PlaneHypothesis::PlaneStrain && j == kZZ) continue;
        Vec4 plus = de, minus = de;
        // Voigt column 3 is 2 e12: the tensor component moves by eps/2.
        const double move = j == kXY ? eps / 2 : eps;
        plus[j] += move;
        minus[j] -= move;
        const Result rp = step(law, c.sn, vn, plus, c.dt), rm = step(law, c.sn, vn, minus, c.dt);
        for (int i = 0; i < 4; ++i) {
          const double fd = (rp.stress[i] - rm.stress[i]) / (2 * eps);
          EXPECT_NEAR(D(i, j), fd, 1e-5 * kE) << c.name << " D(" << i << "," << j << ")";
        }
      }
      const Result r = step(law, c.sn, vn, de, c.dt);
      const VoigtTangent symmetric = 0.5 * (D + D.transpose());
      EXPECT_LT((r.tangent - symmetric).norm(), 1e-12 * D.norm()) << c.name;
      if (c.p > 0) {
        EXPECT_GT((D - D.transpose()).norm(), 1e-6 * D.norm()) << c.name << ": non-associated";
      }
    }
  }
}

TEST(ViscDruckerPrager, NoStrainIncrementGivesTheElasticMatrix) {
  const ViscDruckerPrager law = lawOf(PlaneHypothesis::Axisymmetric);
  const Result r = step(law, kLoaded, {0.002, 1, 1, 2}, {0, 0, 0, 0}, 10.0);
  const double lambda = kK - 2 * kMu / 3;
  EXPECT_NEAR(r.tangent(kXX, kYY), lambda, 1e-9 * kE);
  EXPECT_NEAR(r.tangent(kYY, kYY), lambda + 2 * kMu, 1e-9 * kE);
  EXPECT_NEAR(r.tangent(kXY, kXY), kMu, 1e-9 * kE);
  // The stress still relaxes over the step (creep at fixed strain).
  EXPECT_GT(r.variables[0], 0.002);
  EXPECT_GT(r.stress[1], kLoaded[1]);
}

TEST(ViscDruckerPrager, RefusesPlaneStressAndBadParameters) {
  EXPECT_THROW(lawOf(PlaneHypothesis::PlaneStress), Error);
  ViscDruckerPragerParameters p;
  p.young = kE;
  p.poisson = kNu;
  p.material = rock();
  p.material.pUlt = 0.01;  // below P_PIC
  EXPECT_THROW(ViscDruckerPrager(p, PlaneHypothesis::Axisymmetric), Error);
  p.material = rock();
  p.material.pref = 0;
  EXPECT_THROW(ViscDruckerPrager(p, PlaneHypothesis::Axisymmetric), Error);
}
