// The Drucker-Prager laws (DRUCK_PRAGER, DRUCK_PRAG_N_A) at one material point,
// against closed forms derived by hand, and through the element and the Newton
// driver.
//
// Triaxial compression (AXIS, y the axis): the confining pressure Pc on every face,
// then the axial strain grows while s_rr = s_tt = -Pc. With Delta = -s_yy - Pc the
// deviator, q = Delta and I1 = -3 Pc - Delta, so the cone is reached at
//   Delta_y = (SY + 3 A Pc) / (1 - A)
// and past it (1 - A) Delta - 3 A Pc = R(p): p = R^-1((1 - A) Delta - 3 A Pc). The
// flow direction stays 3/2 s / q + A 1 = (1/2 + A, -1 + A, 1/2 + A) (rr, yy, tt),
// so the axial strain is
//   eps_yy = (s_yy - 2 nu s_rr) / E + (A - 1) p,
// exact for the implicit return (the direction does not turn), whatever the steps.
// Apex: hydrostatic extension eps = e 1 from the natural state, trial s = 0 and
// I1_e = 9 K e; the return to the apex gives A (9 K e - 9 K A dp) = SY + H dp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "../support/square_mesh.hpp"
#include "analysis/mechanical_system.hpp"
#include "analysis/static_nonlinear.hpp"
#include "core/error.hpp"
#include "expr/expression.hpp"
#include "../support/material_point.hpp"
#include "mechanics/drucker_prager.hpp"
#include "mechanics/plane_element.hpp"

using namespace aster;
using namespace aster::mechanics;

namespace {

constexpr double kE = 1000, kNu = 0.3, kA = 0.2, kSy = 1.0;
const double kK = kE / (3 * (1 - 2 * kNu)), kMu = kE / (2 * (1 + kNu));

DruckerPragerParameters linear(double H = 50, double pUltimate = 0.05) {
  DruckerPragerParameters p;
  p.young = kE;
  p.poisson = kNu;
  p.alpha = kA;
  p.yield = kSy;
  p.ultimateStrain = pUltimate;
  p.hardening = DruckerPragerParameters::Hardening::Linear;
  p.slope = H;
  return p;
}

DruckerPragerParameters parabolic(double syUltimate = 1.6, bool associated = true, double dilatancy = 0) {
  DruckerPragerParameters p = linear();
  p.hardening = DruckerPragerParameters::Hardening::Parabolic;
  p.ultimateYield = syUltimate;
  p.associated = associated;
  p.dilatancy = dilatancy;
  return p;
}

using Point = test_support::MaterialPoint;

Eigen::Matrix2d diag(double xx, double yy) {
  Eigen::Matrix2d e = Eigen::Matrix2d::Zero();
  e(0, 0) = xx;
  e(1, 1) = yy;
  return e;
}

// eps_yy given; eps_rr = eps_tt found by Newton so that s_rr = s_tt = -Pc.
LawOutput<VoigtTangent> triaxialStep(Point& point, double eyy, double Pc) {
  double err = point.strain(0, 0);
  std::vector<double> v;
  LawOutput<VoigtTangent> out;
  for (int it = 0; it < 60; ++it) {
    out = point.at(diag(err, eyy), err, v);
    const double r = out.stress(0, 0) + Pc;
    if (std::fabs(r) <= 1e-13 * std::max(1.0, Pc)) break;
    err -= r / (out.tangent(kXX, kXX) + out.tangent(kXX, kZZ));
  }
  EXPECT_NEAR(out.stress(0, 0), -Pc, 1e-11 * std::max(1.0, Pc));
  EXPECT_NEAR(out.stressZZ, -Pc, 1e-11 * std::max(1.0, Pc));
  point.accept(diag(err, eyy), err, out, v);
  return out;
}

struct TriaxialCheck {
  double maxPlasticStrain = 0;
  int plasticSteps = 0;
};

// Confine (hydrostatic, elastic), then compress along y by steps; every step against
// the closed forms above. pOf: p from R(p) = value.
template <class InverseRadius>
TriaxialCheck triaxial(const DruckerPragerParameters& parameters, double Pc, InverseRadius pOf) {
  DruckerPrager law(parameters, PlaneHypothesis::Axisymmetric);
  Point point(law);
  const double e0 = -Pc / (3 * kK);
  std::vector<double> v;
  auto out = point.at(diag(e0, e0), e0, v);
  point.accept(diag(e0, e0), e0, out, v);
  EXPECT_EQ(v[2], 0.0);
  const double deltaYield = (kSy + 3 * kA * Pc) / (1 - kA);
  TriaxialCheck check;
  bool yielded = false;
  for (int step = 1; step <= 80; ++step) {
    const double eyy = e0 - step * 2.5e-4;
    out = triaxialStep(point, eyy, Pc);
    const double syy = out.stress(1, 1), delta = -syy - Pc;
    // Elastic until the deviator reaches Delta_y (softening then lowers it).
    yielded = yielded || delta >= deltaYield * (1 - 1e-10);
    if (!yielded) {
      EXPECT_NEAR(eyy, (syy + 2 * kNu * Pc) / kE, 1e-13);
      EXPECT_EQ(point.variables[2], 0.0);
      continue;
    }
    ++check.plasticSteps;
    const double p = pOf((1 - kA) * delta - 3 * kA * Pc);
    EXPECT_NEAR(point.variables[0], p, 1e-10 * std::max(p, 1e-3)) << "step " << step;
    EXPECT_NEAR(point.variables[1], 3 * kA * p, 1e-10 * std::max(p, 1e-3));
    if (p > 1e-9) {
      EXPECT_EQ(point.variables[2], 1.0);
    }
    EXPECT_NEAR(eyy, (syy + 2 * kNu * Pc) / kE + (kA - 1) * p, 1e-12) << "step " << step;
    check.maxPlasticStrain = p;
  }
  return check;
}

TEST(DruckerPrager, TriaxialCompressionLinearHardening) {
  const auto P = linear(50, 0.05);
  for (double Pc : {0.0, 2.0, 10.0}) {
    SCOPED_TRACE(Pc);
    const auto check = triaxial(P, Pc, [&](double R) { return (R - kSy) / P.slope; });
    EXPECT_GT(check.plasticSteps, 10);
    EXPECT_GT(check.maxPlasticStrain, 1e-3);
  }
}

TEST(DruckerPrager, TriaxialCompressionLinearHardeningPastUltimate) {
  // P_ULTM small: the radius freezes at SY + H P_ULTM and the deviator stays there.
  const auto P = linear(50, 1e-3);
  DruckerPrager law(P, PlaneHypothesis::Axisymmetric);
  Point point(law);
  const double Pc = 2.0, e0 = -Pc / (3 * kK);
  std::vector<double> v;
  auto out = point.at(diag(e0, e0), e0, v);
  point.accept(diag(e0, e0), e0, out, v);
  for (int step = 1; step <= 40; ++step) out = triaxialStep(point, e0 - step * 2.5e-4, Pc);
  const double delta = -out.stress(1, 1) - Pc;
  EXPECT_NEAR(delta, (kSy + P.slope * 1e-3 + 3 * kA * Pc) / (1 - kA), 1e-11);
  EXPECT_GT(point.variables[0], 1e-3);
}

TEST(DruckerPrager, TriaxialCompressionParabolicHardening) {
  for (double syUltimate : {1.6, 0.5}) {  // hardening and softening
    const auto P = parabolic(syUltimate);
    const double a = std::sqrt(syUltimate / kSy);
    SCOPED_TRACE(syUltimate);
    // R = SY (1 - (1 - a) p / P_ULTM)^2 up to P_ULTM.
    const auto check = triaxial(P, 3.0, [&](double R) {
      return P.ultimateStrain * (1 - std::sqrt(R / kSy)) / (1 - a);
    });
    EXPECT_GT(check.plasticSteps, 10);
  }
}

// Hydrostatic extension past the apex, from the natural state in one step.
TEST(DruckerPrager, ReturnToTheApexIsExact) {
  for (double H : {50.0, 0.0}) {
    SCOPED_TRACE(H);
    const auto P = linear(H, 0.5);
    for (auto hypothesis : {PlaneHypothesis::Axisymmetric, PlaneHypothesis::PlaneStrain}) {
      DruckerPrager law(P, hypothesis);
      Point point(law);
      const double e = 0.01;
      const double ezz = hypothesis == PlaneHypothesis::Axisymmetric ? e : 0.0;
      std::vector<double> v;
      const auto out = point.at(diag(e, e), ezz, v);
      const double trace = 2 * e + ezz;
      const double dp = (3 * kK * kA * trace - kSy) / (9 * kK * kA * kA + H);
      const double mean = kK * trace - 3 * kK * kA * dp;
      EXPECT_EQ(v[2], 2.0);
      EXPECT_NEAR(v[0], dp, 1e-14);
      EXPECT_NEAR(v[1], 3 * kA * dp, 1e-14);
      EXPECT_NEAR(out.stress(0, 0), mean, 1e-12 * mean);
      EXPECT_NEAR(out.stress(1, 1), mean, 1e-12 * mean);
      EXPECT_NEAR(out.stressZZ, mean, 1e-12 * mean);
      EXPECT_EQ(out.stress(0, 1), 0.0);
      // On the yield surface: q = 0 and A I1 = R(p).
      EXPECT_NEAR(kA * 3 * mean, kSy + H * dp, 1e-12);
    }
  }
}

// A trial state with a small deviator, beyond the apex: the deviator vanishes too.
TEST(DruckerPrager, ApexWithADeviatoricTrial) {
  const auto P = linear(50, 0.5);
  DruckerPrager law(P, PlaneHypothesis::Axisymmetric);
  Point point(law);
  Eigen::Matrix2d e = diag(0.012, 0.010);
  e(0, 1) = e(1, 0) = 0.001;
  std::vector<double> v;
  const auto out = point.at(e, 0.011, v);
  const double trace = 0.033;
  const double dp = (3 * kK * kA * trace - kSy) / (9 * kK * kA * kA + P.slope);
  const double mean = kK * trace - 3 * kK * kA * dp;
  EXPECT_EQ(v[2], 2.0);
  EXPECT_NEAR(out.stress(0, 0), mean, 1e-12 * mean);
  EXPECT_NEAR(out.stress(1, 1), mean, 1e-12 * mean);
  EXPECT_NEAR(out.stressZZ, mean, 1e-12 * mean);
  EXPECT_NEAR(out.stress(0, 1), 0.0, 1e-12 * mean);
}

// dS/dE against central differences of the stress (Voigt: the xy column is the
// derivative in 2 e_xy).
void expectTangent(const Point& point, const Eigen::Matrix2d& e, double ezz, const char* where) {
  SCOPED_TRACE(where);
  std::vector<double> v;
  const auto out = point.at(e, ezz, v);
  const double h = 1e-8;
  VoigtTangent fd;
  for (int j = 0; j < 4; ++j) {
    Eigen::Matrix2d dE = Eigen::Matrix2d::Zero();
    double dzz = 0;
    if (j == kXX) dE(0, 0) = h;
    if (j == kYY) dE(1, 1) = h;
    if (j == kZZ) dzz = h;
    if (j == kXY) dE(0, 1) = dE(1, 0) = h / 2;
    const auto plus = point.at(e + dE, ezz + dzz, v, 0.0, false);
    const auto minus = point.at(e - dE, ezz - dzz, v, 0.0, false);
    fd(kXX, j) = (plus.stress(0, 0) - minus.stress(0, 0)) / (2 * h);
    fd(kYY, j) = (plus.stress(1, 1) - minus.stress(1, 1)) / (2 * h);
    fd(kZZ, j) = (plus.stressZZ - minus.stressZZ) / (2 * h);
    fd(kXY, j) = (plus.stress(0, 1) - minus.stress(0, 1)) / (2 * h);
  }
  EXPECT_LE((out.tangent - fd).cwiseAbs().maxCoeff(), 1e-6 * kE) << "analytic\n"
                                                                  << out.tangent << "\nfinite differences\n"
                                                                  << fd;
}

TEST(DruckerPrager, ConsistentTangentAgainstFiniteDifferences) {
  const std::vector<std::pair<const char*, DruckerPragerParameters>> laws = {
      {"linear", linear(50, 0.05)},
      {"parabolic", parabolic(1.6)},
      {"parabolic softening", parabolic(0.5)},
      {"non-associated", parabolic(1.6, false, 0.05)},
      {"non-associated, negative dilatancy", parabolic(0.8, false, -0.1)},
  };
  for (const auto& [name, P] : laws) {
    SCOPED_TRACE(name);
    DruckerPrager law(P, PlaneHypothesis::Axisymmetric);
    Point point(law);
    // A plastic state on the cone first (accepted), then increments from it.
    Eigen::Matrix2d e = diag(0.001, -0.004);
    e(0, 1) = e(1, 0) = 0.0007;
    std::vector<double> v;
    auto out = point.at(e, 0.001, v);
    ASSERT_EQ(v[2], 1.0);
    point.accept(e, 0.001, out, v);
    Eigen::Matrix2d de = diag(0.0002, -0.001);
    de(0, 1) = de(1, 0) = 0.0003;
    expectTangent(point, e + de, 0.0012, "cone");
    expectTangent(point, e - 0.2 * de, 0.001, "elastic unloading");
    Point fresh(law);
    expectTangent(fresh, diag(1e-4, -2e-4), 5e-5, "elastic from the natural state");
  }
  // The apex (associated, hardening left).
  DruckerPrager law(linear(50, 0.5), PlaneHypothesis::Axisymmetric);
  Point point(law);
  Eigen::Matrix2d e = diag(0.012, 0.010);
  e(0, 1) = e(1, 0) = 0.001;
  expectTangent(point, e, 0.011, "apex");
  // The apex of the non-associated law (dilatancy left: a small extension).
  DruckerPrager nonAssociated(parabolic(1.6, false, 0.05), PlaneHypothesis::Axisymmetric);
  Point fromRest(nonAssociated);
  Eigen::Matrix2d small = diag(0.00082, 0.0008);
  small(0, 1) = small(1, 0) = 1e-5;
  std::vector<double> v;
  fromRest.at(small, 0.0008, v);
  ASSERT_EQ(v[2], 2.0);
  expectTangent(fromRest, small, 0.0008, "non-associated apex");
}

// With no increment yet (a step's prediction) after a plastic step, the tangent is the
// continuum elastic-plastic one: the one-sided derivative along continued loading.
TEST(DruckerPrager, PredictionTangentIsTheContinuumOne) {
  const std::vector<std::pair<const char*, DruckerPragerParameters>> laws = {
      {"linear", linear(50, 0.05)},
      {"parabolic", parabolic(1.6)},
      {"non-associated", parabolic(1.6, false, 0.05)},
  };
  for (const auto& [name, P] : laws) {
    SCOPED_TRACE(name);
    DruckerPrager law(P, PlaneHypothesis::Axisymmetric);
    Point point(law);
    Eigen::Matrix2d e = diag(0.001, -0.004);
    e(0, 1) = e(1, 0) = 0.0007;
    const double ezz = 0.001;
    std::vector<double> v;
    auto out = point.at(e, ezz, v);
    ASSERT_EQ(v[2], 1.0);
    point.accept(e, ezz, out, v);
    const auto rest = point.at(e, ezz, v);
    EXPECT_NEAR(v[0], point.variables[0], 1e-15);  // no increment: no plastic flow (to rounding)
    // Continue loading along the same direction.
    const double h = 1e-7;
    const auto ahead = point.at(e * (1 + h), ezz * (1 + h), v, 0.0, false);
    ASSERT_EQ(v[2], 1.0);
    const Eigen::Vector4d de(h * e(0, 0), h * e(1, 1), h * ezz, 2 * h * e(0, 1));
    const Eigen::Vector4d predicted = rest.tangent * de;
    const Eigen::Vector4d actual(ahead.stress(0, 0) - out.stress(0, 0), ahead.stress(1, 1) - out.stress(1, 1),
                                 ahead.stressZZ - out.stressZZ, ahead.stress(0, 1) - out.stress(0, 1));
    EXPECT_LE((predicted - actual).cwiseAbs().maxCoeff(), 1e-5 * actual.cwiseAbs().maxCoeff())
        << predicted.transpose() << "\n" << actual.transpose();
  }
}

// The prediction follows the previous step's INDIPLAS alone, as code_aster's RIGI_MECA_TANG:
// with INDIPLAS = 1 and a stress inside the cone (an initial state, say) the tangent is
// still the continuum one, D = De - v v^T / h, v = 3 mu s / q + 3 K A 1, h = 3 mu + 9 K A^2 + H.
TEST(DruckerPrager, PredictionFollowsThePreviousIndicator) {
  constexpr double H = 50;
  DruckerPrager law(linear(H, 0.05), PlaneHypothesis::PlaneStrain);
  Point point(law);
  const double sigma[4] = {-1.0, -1.2, -1.0, 0.1};
  std::copy(sigma, sigma + 4, point.stress);
  point.variables = {0.01, 3 * kA * 0.01, 1.0};
  const double mean = (sigma[0] + sigma[1] + sigma[2]) / 3;
  const double s[4] = {sigma[0] - mean, sigma[1] - mean, sigma[2] - mean, sigma[3]};
  const double q = std::sqrt(1.5 * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + 2 * s[3] * s[3]));
  ASSERT_LT(q + kA * 3 * mean - (kSy + H * 0.01), -0.5);  // well inside the cone
  std::vector<double> v;
  const auto rest = point.at(Eigen::Matrix2d::Zero(), 0, v);
  EXPECT_EQ(v[2], 0.0);  // no flow
  const double h = 3 * kMu + 9 * kK * kA * kA + H;
  double g[4];
  for (int i = 0; i < 4; ++i) g[i] = 3 * kMu * s[i] / q + (i < 3 ? 3 * kK * kA : 0.0);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const double elastic = i < 3 && j < 3 ? kK + 2 * kMu * ((i == j ? 1.0 : 0.0) - 1.0 / 3.0) : i == j ? kMu : 0.0;
      EXPECT_NEAR(rest.tangent(i, j), elastic - g[i] * g[j] / h, 1e-12 * kE) << i << ", " << j;
    }
}

TEST(DruckerPrager, NonAssociatedTangentIsUnsymmetric) {
  DruckerPrager law(parabolic(1.6, false, 0.05), PlaneHypothesis::PlaneStrain);
  EXPECT_FALSE(law.symmetricTangent());
  EXPECT_TRUE(DruckerPrager(linear(), PlaneHypothesis::PlaneStrain).symmetricTangent());
  Point point(law);
  std::vector<double> v;
  const auto out = point.at(diag(0.002, -0.006), 0, v);
  ASSERT_EQ(v[2], 1.0);
  EXPECT_GT(std::fabs(out.tangent(kXX, kYY) - out.tangent(kYY, kXX)), 1e-3);
}

TEST(DruckerPrager, RefusesWhatCodeAsterRefuses) {
  EXPECT_THROW(DruckerPrager(linear(), PlaneHypothesis::PlaneStress), Error);
  auto nonAssociatedLinear = linear();
  nonAssociatedLinear.associated = false;
  EXPECT_THROW(DruckerPrager(nonAssociatedLinear, PlaneHypothesis::PlaneStrain), Error);
  auto noUltimate = linear();
  noUltimate.ultimateStrain = 0;
  EXPECT_THROW(DruckerPrager(noUltimate, PlaneHypothesis::PlaneStrain), Error);
}

// DRUCK_PRAG_N_A's dilatancy vanishes at P_ULTM: a hydrostatic extension too large for
// it to reach the apex has no return (the driver then cuts the step).
TEST(DruckerPrager, ApexOutOfReachOfTheNonAssociatedFlowIsRefused) {
  DruckerPrager law(parabolic(1.6, false, 0.05), PlaneHypothesis::Axisymmetric);
  Point point(law);
  std::vector<double> v;
  EXPECT_THROW(point.at(diag(0.01, 0.01), 0.01, v), Error);
}

// The element with a non-symmetric law assembles its whole matrix: K = df/du by
// central differences of the internal force, from a plastic accepted state (PETIT,
// and GROT_GDEP with its geometric stiffness).
TEST(DruckerPrager, ElementMatrixOfTheNonAssociatedLawIsTheExactDerivative) {
  for (auto kinematics : {Kinematics::SmallStrain, Kinematics::GreenLagrange})
    for (auto hypothesis : {PlaneHypothesis::PlaneStrain, PlaneHypothesis::Axisymmetric}) {
      SCOPED_TRACE(std::string(planeHypothesisName(hypothesis)) +
                   (kinematics == Kinematics::SmallStrain ? " PETIT" : " GROT_GDEP"));
      auto law = std::make_shared<const DruckerPrager>(parabolic(1.6, false, 0.05), hypothesis);
      PlaneElement<CellType::QUAD4, BehaviourLaw> element(std::shared_ptr<const BehaviourLaw>(law), kinematics);
      using E = PlaneElement<CellType::QUAD4, BehaviourLaw>;
      E::Coords X;
      X << 1.0, 0.0, 2.0, 0.1, 2.1, 1.0, 0.9, 1.2;
      E::Vector un, u;
      un << 0, 0, 0.002, 0.0002, 0.0022, -0.004, 0.0003, -0.0035;
      u = un;
      u(5) -= 0.001;
      u(7) -= 0.0008;
      const int points = element.gaussPointCount();
      std::vector<double> stress(4 * points), variables(3 * points), newVariables(3 * points);
      element.gaussStresses(X, un, stress.data());
      ElementHistory history;
      history.displacement = un.data();
      history.stress = stress.data();
      history.variables = variables.data();  // the natural state's: the step from un is plastic
      E::Vector f;
      E::Matrix K;
      element.internalForce(X, u, history, newVariables.data(), &f, &K);
      int plastic = 0;
      for (int q = 0; q < points; ++q) plastic += newVariables[3 * q + 2] == 1.0;
      EXPECT_GT(plastic, 0);
      E::Matrix fd;
      const double h = 1e-9;
      for (int j = 0; j < E::dofs; ++j) {
        E::Vector up = u, um = u, fp, fm;
        up(j) += h;
        um(j) -= h;
        element.internalForce(X, up, history, newVariables.data(), &fp, nullptr);
        element.internalForce(X, um, history, newVariables.data(), &fm, nullptr);
        fd.col(j) = (fp - fm) / (2 * h);
      }
      EXPECT_LE((K - fd).cwiseAbs().maxCoeff(), 1e-5 * K.cwiseAbs().maxCoeff()) << K << "\n\n" << fd;
      EXPECT_GT((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-6 * K.cwiseAbs().maxCoeff());
    }
}

// A small non-associated study through the driver: the system says its tangent is
// unsymmetric (UMFPACK solves it), and Newton converges quadratically.
TEST(DruckerPrager, NewtonConvergesQuadraticallyOnANonAssociatedStudy) {
  auto mesh = std::make_shared<mesh::Mesh>(test_support::squareMesh(3, mesh::CellType::QUAD8));
  auto model = std::make_shared<model::Model>(mesh);
  std::vector<int> all(mesh->cellCount());
  for (int c = 0; c < mesh->cellCount(); ++c) all[c] = c;
  model->assign(all, model::Modelisation::PlaneStrain);
  model::MechanicalLoad load;
  load.imposed.push_back({mesh->nodesOfCells(mesh->cellGroup("GAUCHE")), 0, model::SpaceFunction(0.0)});
  load.imposed.push_back({mesh->nodesOfCells(mesh->cellGroup("BAS")), 1, model::SpaceFunction(0.0)});
  load.imposed.push_back({mesh->nodesOfCells(mesh->cellGroup("HAUT")), 1,
                          model::SpaceFunction(expr::Expression::compile("-0.002 * INST * (1 + X)", {"X", "INST"}))});
  analysis::MechanicalProblem problem;
  problem.model = model;
  problem.loads.push_back({&load, nullptr});
  problem.kinematics.assign(model->cells().size(), Kinematics::SmallStrain);
  problem.relations.assign(model->cells().size(),
                           std::make_shared<DruckerPrager>(parabolic(1.6, false, 0.05), PlaneHypothesis::PlaneStrain));
  analysis::MechanicalSystem system(problem);
  EXPECT_FALSE(system.symmetricTangent());
  analysis::NewtonSettings settings;
  settings.resiGlobRela = 1e-13;
  settings.iterGlobMaxi = 20;
  analysis::StaticNonlinear newton(system, nullptr, settings);
  Eigen::VectorXd U = Eigen::VectorXd::Zero(newton.unknownCount());
  std::vector<std::vector<double>> residuals;
  double maxP = 0;
  newton.run(U, {0.0, 1.0, 2.0, 3.0}, [&](const analysis::ConvergedInstant& c) {
    residuals.push_back(c.residuals);
    std::vector<int> offsets;
    std::vector<double> s;
    system.gaussVariables(offsets, s);
    for (std::size_t q = 0; q < s.size() / 3; ++q) maxP = std::max(maxP, s[3 * q]);
  });
  ASSERT_EQ(residuals.size(), 3u);
  EXPECT_GT(maxP, 1e-3);
  int checked = 0;
  for (const auto& seq : residuals)
    for (std::size_t k = 1; k + 1 < seq.size(); ++k) {
      if (seq[k] > 1e-3 || seq[k + 1] < 1e-12) continue;
      EXPECT_LE(seq[k + 1], 1e3 * seq[k] * seq[k]) << "iteration " << k + 1 << ": " << seq[k] << " -> " << seq[k + 1];
      ++checked;
    }
  EXPECT_GE(checked, 2);
}

}  // namespace
