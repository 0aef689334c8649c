// LEMAITRE and NORTON at one material point, against closed forms derived by hand:
// a bar (AXIS, uniaxial stress along the axis y, s_rr = s_tt = 0) under constant
// stress s creeps as
//   Norton:   eps_v(t) = (s / K)^N t                       (exact for the theta scheme)
//   Lemaitre: p(t) = ((N/M + 1) (s / K)^N t)^(1 / (N/M + 1))   (dp/dt = (s/K)^N p^(-N/M))
// and relaxes at constant axial strain as d s/dt = -E (s/K)^N, whence
//   s(t) = (s0^(1-N) + (N - 1) E t / K^N)^(-1 / (N-1)).
// The time discretization error falls as dt (PARM_THETA = 1) and dt^2 (0.5). The
// consistent tangent is checked against central finite differences of the stress.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/error.hpp"
#include "../support/material_point.hpp"
#include "mechanics/lemaitre_viscoplasticity.hpp"

using namespace aster;
using namespace aster::mechanics;

namespace {

constexpr double kE = 200e3, kNu = 0.3;

LemaitreParameters tight(LemaitreParameters p) {
  p.maxIterations = 2000;
  p.tolerance = 1e-11;  // |F| in MPa: the root to rounding
  return p;
}

using Point = test_support::MaterialPoint;

// AXIS, one step of dt: e_rr = e_tt such that s_rr = s_tt = 0, and either the axial
// stress s_yy = target (stressControl) or the axial strain e_yy = target.
void uniaxialStep(Point& point, double target, bool stressControl, double dt) {
  Eigen::Matrix2d e = point.strain;
  double ett = point.strainZZ;
  if (!stressControl) e(1, 1) = target;
  std::vector<double> v;
  LawOutput<VoigtTangent> out;
  for (int it = 0; it < 2000; ++it) {  // (Runge-Kutta's elastic tangent converges linearly)
    out = point.at(e, ett, v, dt);
    // Unknowns: the lateral strain (e_rr = e_tt), and e_yy under stress control.
    const double r1 = out.stress(0, 0);
    const double a11 = out.tangent(kXX, kXX) + out.tangent(kXX, kZZ);
    if (!stressControl) {
      if (std::fabs(r1) <= 1e-12 * std::fabs(out.stress(1, 1))) break;
      e(0, 0) -= r1 / a11;
      ett -= r1 / a11;
      continue;
    }
    const double r2 = out.stress(1, 1) - target;
    if (std::fabs(r1) <= 1e-12 * std::fabs(target) && std::fabs(r2) <= 1e-12 * std::fabs(target)) break;
    const double a12 = out.tangent(kXX, kYY), a21 = out.tangent(kYY, kXX) + out.tangent(kYY, kZZ),
                 a22 = out.tangent(kYY, kYY);
    const double det = a11 * a22 - a12 * a21;
    const double dl = -(a22 * r1 - a12 * r2) / det, da = -(a11 * r2 - a21 * r1) / det;
    e(0, 0) += dl;
    ett += dl;
    e(1, 1) += da;
  }
  EXPECT_NEAR(out.stress(0, 0), 0.0, 1e-9 * std::fabs(out.stress(1, 1)));
  EXPECT_NEAR(out.stressZZ, 0.0, 1e-9 * std::fabs(out.stress(1, 1)));
  point.accept(e, ett, out, v);
}

double variable(const Point& point, const char* name) {
  const auto names = point.law.internalVariableNames();
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return point.variables[i];
  ADD_FAILURE() << "no variable " << name;
  return 0.0;
}

TEST(Lemaitre, NamesItsVariablesAsCodeAster) {
  const LemaitreViscoplasticity lemaitre(lemaitreParameters(kE, kNu, 3, 0.01, 0.2, 1), PlaneHypothesis::PlaneStrain);
  EXPECT_EQ(lemaitre.internalVariableNames(), (std::vector<std::string>{"EPSPEQ", "VIDE"}));
  const LemaitreViscoplasticity norton(nortonParameters(kE, kNu, 3, 0.01, 0, 1), PlaneHypothesis::Axisymmetric);
  EXPECT_EQ(norton.internalVariableNames(),
            (std::vector<std::string>{"EPSPXX", "EPSPYY", "EPSPZZ", "EPSPXY", "EPSPXZ", "EPSPYZ", "VIDE"}));
  EXPECT_TRUE(norton.predictsFromAcceptedState());
}

TEST(Lemaitre, RefusesParametersOutOfRange) {
  EXPECT_THROW(lemaitreParameters(kE, kNu, 0, 0.01, 0, 1), Error);         // N
  EXPECT_THROW(lemaitreParameters(kE, kNu, 3, -0.01, 0, 1), Error);        // UN_SUR_K
  EXPECT_THROW(lemaitreParameters(kE, kNu, 3, 0.01, -1, 1), Error);        // UN_SUR_M
  EXPECT_THROW(lemaitreParameters(kE, kNu, 3, 0.01, 0, 0.7), Error);       // PARM_THETA
  EXPECT_THROW(nortonParameters(kE, kNu, 3, 0.01, 0.5, 1), Error);         // NORTON with UN_SUR_M
  EXPECT_THROW(LemaitreViscoplasticity(lemaitreParameters(kE, kNu, 3, 0.01, 0, 1), PlaneHypothesis::PlaneStress),
               Error);
  try {
    lemaitreParameters(kE, kNu, 3, -0.01, 0, 1);
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("UN_SUR_K"), std::string::npos) << e.what();
  }
}

// Norton creep under a constant stress, loaded at once (dt = 0: elastic), then held.
TEST(Lemaitre, NortonCreepUnderConstantStressIsExact) {
  const double n = 4.5, K = 500, s = 150;
  for (double theta : {1.0, 0.5}) {
    const LemaitreViscoplasticity law(tight(nortonParameters(kE, kNu, n, 1 / K, 0, theta)),
                                      PlaneHypothesis::Axisymmetric);
    Point point(law);
    uniaxialStep(point, s, true, 0.0);
    EXPECT_NEAR(point.strain(1, 1), s / kE, 1e-12);
    double t = 0;
    for (double dt : {10.0, 50.0, 200.0, 1000.0}) {
      uniaxialStep(point, s, true, dt);
      t += dt;
      const double creep = std::pow(s / K, n) * t;
      EXPECT_NEAR(point.strain(1, 1), s / kE + creep, 1e-9 * creep) << "theta " << theta << " t " << t;
      EXPECT_NEAR(variable(point, "EPSPYY"), creep, 1e-9 * creep);
      EXPECT_NEAR(variable(point, "EPSPXX"), -creep / 2, 1e-9 * creep);  // incompressible flow
      EXPECT_NEAR(variable(point, "EPSPZZ"), -creep / 2, 1e-9 * creep);
    }
  }
}

// Lemaitre creep: p(t) = ((N/M + 1) (s/K)^N t)^(1/(N/M + 1)), reached as dt -> 0.
TEST(Lemaitre, LemaitreCreepConvergesToTheClosedForm) {
  const double n = 3, K = 400, invM = 0.25, s = 120, T = 1000;
  const double a = n * invM + 1;
  const double exact = std::pow(a * std::pow(s / K, n) * T, 1 / a);
  const LemaitreViscoplasticity law(tight(lemaitreParameters(kE, kNu, n, 1 / K, invM, 1)),
                                    PlaneHypothesis::Axisymmetric);
  double previousError = 0;
  for (int steps : {200, 400, 800}) {
    Point point(law);
    uniaxialStep(point, s, true, 0.0);
    // Steps growing geometrically (the rate is singular at p = 0): t_k = T (k/steps)^3.
    for (int k = 1; k <= steps; ++k) {
      const double dt = T * (std::pow(double(k) / steps, 3) - std::pow(double(k - 1) / steps, 3));
      uniaxialStep(point, s, true, dt);
    }
    const double p = variable(point, "EPSPEQ");
    EXPECT_NEAR(point.strain(1, 1) - s / kE, p, 1e-9 * p);  // uniaxial: eps_v,yy = p
    const double error = std::fabs(p - exact) / exact;
    EXPECT_LT(error, 5e-3) << steps << " steps";
    if (previousError > 0) {
      EXPECT_NEAR(previousError / error, 2.0, 0.3) << steps << " steps";
    }
    previousError = error;
  }
}

// Relaxation at constant axial strain: the closed form, first order in dt for theta = 1,
// second order for theta = 0.5.
TEST(Lemaitre, NortonRelaxationConvergesAtTheOrderOfTheScheme) {
  const double n = 3, K = 100, s0 = 200, T = 2e-4;
  const double exact = std::pow(std::pow(s0, 1 - n) + (n - 1) * kE * T / std::pow(K, n), -1 / (n - 1));
  ASSERT_LT(exact, 0.6 * s0);  // a relaxation well under way
  for (double theta : {1.0, 0.5}) {
    const LemaitreViscoplasticity law(tight(nortonParameters(kE, kNu, n, 1 / K, 0, theta)),
                                      PlaneHypothesis::Axisymmetric);
    std::vector<double> errors;
    for (int steps : {10, 20, 40}) {
      Point point(law);
      uniaxialStep(point, s0 / kE, false, 0.0);
      EXPECT_NEAR(point.stress[1], s0, 1e-9 * s0);
      for (int k = 0; k < steps; ++k) uniaxialStep(point, s0 / kE, false, T / steps);
      errors.push_back(std::fabs(point.stress[1] - exact) / exact);
    }
    const double order = theta == 1.0 ? 1.0 : 2.0;
    for (int i = 0; i + 1 < 3; ++i)
      EXPECT_NEAR(std::log2(errors[i] / errors[i + 1]), order, 0.15) << "theta " << theta << " errors " << errors[i];
    EXPECT_LT(errors.back(), theta == 1.0 ? 0.02 : 1e-3);
  }
}

// NORTON by Runge-Kutta (code_aster's default): the creep and the relaxation above, to
// the tolerance of its error control whatever the step.
LemaitreParameters rungeKutta(LemaitreParameters p, double tolerance) {
  p.rungeKutta = true;
  p.tolerance = tolerance;
  return p;
}

TEST(Lemaitre, NortonRungeKuttaCreepAndRelaxationMeetTheClosedForms) {
  {
    const double n = 4.5, K = 500, s = 150;
    const LemaitreViscoplasticity law(rungeKutta(nortonParameters(kE, kNu, n, 1 / K, 0, 1), 1e-8),
                                      PlaneHypothesis::Axisymmetric);
    Point point(law);
    uniaxialStep(point, s, true, 0.0);
    double t = 0;
    for (double dt : {0.5, 1.0, 2.0}) {
      uniaxialStep(point, s, true, dt);
      t += dt;
      const double creep = std::pow(s / K, n) * t;
      EXPECT_NEAR(variable(point, "EPSPYY"), creep, 1e-6 * creep) << "t " << t;
      EXPECT_NEAR(variable(point, "VIDE"), creep, 1e-6 * creep) << "t " << t;  // the cumulated p
      EXPECT_NEAR(point.strain(1, 1), s / kE + creep, 1e-6 * creep);
    }
  }
  // Relaxation at a fixed strain (D_PLAN, e_xx = e, the others 0: the scheme's linear
  // strain path is then exact): the deviator keeps its direction and its equivalent q
  // follows dq/dt = -3 mu (q/K)^N, q^(1-N) = q0^(1-N) + (N - 1) 3 mu t / K^N, q0 = 2 mu e;
  // s_xx - s_yy = q (the mean stress stays).
  const double n = 3, K = 100, e = 1e-3, T = 3e-4;
  const double mu = kE / (2 * (1 + kNu)), q0 = 2 * mu * e;
  const double exact = std::pow(std::pow(q0, 1 - n) + (n - 1) * 3 * mu * T / std::pow(K, n), -1 / (n - 1));
  ASSERT_LT(exact, 0.6 * q0);
  const LemaitreViscoplasticity law(rungeKutta(nortonParameters(kE, kNu, n, 1 / K, 0, 1), 1e-9),
                                    PlaneHypothesis::PlaneStrain);
  for (int steps : {1, 4}) {
    Point point(law);
    Eigen::Matrix2d strain = Eigen::Matrix2d::Zero();
    strain(0, 0) = e;
    std::vector<double> v;
    point.accept(strain, 0, point.at(strain, 0, v, 0.0), v);
    const double mean = (point.stress[0] + point.stress[1] + point.stress[2]) / 3;
    for (int k = 0; k < steps; ++k) {
      const auto out = point.at(strain, 0, v, T / steps);
      point.accept(strain, 0, out, v);
    }
    EXPECT_NEAR(point.stress[0] - point.stress[1], exact, 1e-6 * exact) << steps << " steps";
    EXPECT_NEAR((point.stress[0] + point.stress[1] + point.stress[2]) / 3, mean, 1e-9 * q0);
  }
}

// The tangent against central differences of the stress, at states with a history.
void checkTangent(const LemaitreParameters& parameters, PlaneHypothesis hypothesis) {
  const LemaitreViscoplasticity law(tight(parameters), hypothesis);
  const bool axis = hypothesis == PlaneHypothesis::Axisymmetric;
  Point point(law);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int state = 0; state < 6; ++state) {
    Eigen::Matrix2d e = point.strain;
    double ezz = point.strainZZ;
    e(0, 0) += 1.5e-3 * uniform(random);
    e(1, 1) += 1.5e-3 * uniform(random);
    e(0, 1) = e(1, 0) = e(0, 1) + 1e-3 * uniform(random);
    if (axis) ezz += 1e-3 * uniform(random);
    const double dt = 5.0 * (1 + uniform(random));
    std::vector<double> v;
    const auto out = point.at(e, ezz, v, dt);
    const double h = 1e-8;
    const int columns[4] = {kXX, kYY, kZZ, kXY};
    for (int column : columns) {
      if (column == kZZ && !axis) continue;
      auto perturbed = [&](double sign) {
        Eigen::Matrix2d ep = e;
        double ezzp = ezz;
        if (column == kXX) ep(0, 0) += sign * h;
        if (column == kYY) ep(1, 1) += sign * h;
        if (column == kZZ) ezzp += sign * h;
        if (column == kXY) {  // the engineering shear 2 e_xy
          ep(0, 1) += sign * h / 2;
          ep(1, 0) += sign * h / 2;
        }
        std::vector<double> w;
        const auto o = point.at(ep, ezzp, w, dt);
        return Eigen::Vector4d(o.stress(0, 0), o.stress(1, 1), o.stressZZ, o.stress(0, 1));
      };
      const Eigen::Vector4d fd = (perturbed(1) - perturbed(-1)) / (2 * h);
      for (int row = 0; row < 4; ++row)
        EXPECT_NEAR(out.tangent(row, column), fd(row), 1e-5 * kE)
            << "state " << state << " D(" << row << ", " << column << ")";
    }
    EXPECT_LT((out.tangent - out.tangent.transpose()).norm(), 1e-9 * kE);
    // The state was viscous: the tangent is not the elastic one.
    EXPECT_LT(out.tangent(kXY, kXY), 0.999 * kE / (2 * (1 + kNu))) << "state " << state;
    point.accept(e, ezz, out, v);
  }
  EXPECT_GT(std::fabs(variable(point, law.internalVariableNames()[0].c_str())), 0.0);
}

TEST(Lemaitre, TangentMatchesFiniteDifferencesPlaneStrain) {
  checkTangent(lemaitreParameters(kE, kNu, 4, 1 / 300.0, 0.3, 1), PlaneHypothesis::PlaneStrain);
  checkTangent(lemaitreParameters(kE, kNu, 4, 1 / 300.0, 0.3, 0.5), PlaneHypothesis::PlaneStrain);
  checkTangent(nortonParameters(kE, kNu, 6, 1 / 300.0, 0, 1), PlaneHypothesis::PlaneStrain);
}

TEST(Lemaitre, TangentMatchesFiniteDifferencesAxis) {
  checkTangent(lemaitreParameters(kE, kNu, 4, 1 / 300.0, 0.3, 0.5), PlaneHypothesis::Axisymmetric);
  checkTangent(nortonParameters(kE, kNu, 6, 1 / 300.0, 0, 0.5), PlaneHypothesis::Axisymmetric);
}

// With no time (dt = 0) the law is elastic, whatever the stress.
TEST(Lemaitre, NoTimeNoFlow) {
  const LemaitreViscoplasticity law(nortonParameters(kE, kNu, 3, 1 / 100.0, 0, 1), PlaneHypothesis::PlaneStrain);
  Point point(law);
  Eigen::Matrix2d e = Eigen::Matrix2d::Zero();
  e(0, 0) = 2e-3;
  std::vector<double> v;
  const auto out = point.at(e, 0, v, 0.0);
  const double lambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu)), mu = kE / (2 * (1 + kNu));
  EXPECT_NEAR(out.stress(0, 0), (lambda + 2 * mu) * 2e-3, 1e-9);
  EXPECT_NEAR(out.stressZZ, lambda * 2e-3, 1e-9);
  for (double x : v) EXPECT_EQ(x, 0.0);
}

}  // namespace
