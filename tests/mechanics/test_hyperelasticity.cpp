// ELAS_HYPER (generalised Mooney-Rivlin, hyperelasticity.hpp) against
// independent references: its tangent against central differences of its stress
// (D_PLAN, C_PLAN, at the law and through a GROT_GDEP QUAD4); homogeneous stretches
// and simple shear against the Cauchy stress written by hand from the stretches,
//   sigma = (2/J) dev[(W1 + I1~ W2) B~ - W2 B~^2] + K (J - 1) 1,  B~ = J^(-2/3) F F^T,
// W1 = dW/dI1~ = C10 + 2 C20 (I1~ - 3), W2 = dW/dI2~ = C01; S_zz = 0 in C_PLAN;
// the small-strain limit against ELAS with mu = 2 (C10 + C01) and the bulk K.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "../support/square_mesh.hpp"
#include "analysis/mechanical_system.hpp"
#include "analysis/static_nonlinear.hpp"
#include "core/error.hpp"
#include "expr/expression.hpp"
#include "mechanics/hyperelasticity.hpp"
#include "mechanics/isotropic_elasticity.hpp"
#include "patch_support.hpp"

using namespace aster;
using namespace aster::mechanics;
using namespace testing_support;

namespace {

constexpr double kC10 = 0.7, kC01 = 0.2, kC20 = 0.05, kBulk = 12.0;

struct Result {
  Eigen::Vector4d stress;  // S11, S22, S33, S12
  VoigtTangent tangent;
  double strainZZ;
};

Result run(const Hyperelasticity& law, const Eigen::Matrix2d& E, bool withTangent = true, double strainZZ = 0.0) {
  LawInput in;
  in.strain = E;
  in.strainZZ = strainZZ;
  in.strainIncrement = E;
  const double previousStress[4] = {0, 0, 0, 0}, previousVariables[1] = {0};
  in.previousStress = previousStress;
  in.previousVariables = previousVariables;
  double variables[1] = {-1};
  LawOutput<VoigtTangent> out;
  out.variables = variables;
  law.integrate(in, out, withTangent);
  EXPECT_EQ(variables[0], 0.0);  // VIDE
  Result r;
  r.stress << out.stress(0, 0), out.stress(1, 1), out.stressZZ, out.stress(0, 1);
  EXPECT_EQ(out.stress(0, 1), out.stress(1, 0));
  if (withTangent) r.tangent = out.tangent;
  r.strainZZ = out.strainZZ;
  return r;
}

// The lateral stretch t of a uniaxial stretch l along x making sigma_22 = 0 of
// the hand formula: F = diag(l, t, t) in C_PLAN (sigma_33 = 0 too), F = diag(l, t, 1)
// in D_PLAN. Bisection.
double lateralStretch(double l, PlaneHypothesis h, double c10, double c01, double c20, double bulk);

// The Cauchy stress of the deformation gradient F (3x3) by the formula in the header.
Eigen::Matrix3d handCauchy(const Eigen::Matrix3d& F, double c10, double c01, double c20, double bulk) {
  const double J = F.determinant();
  const Eigen::Matrix3d Bbar = std::pow(J, -2.0 / 3.0) * F * F.transpose();
  const double I1 = Bbar.trace();  // I1~
  const double W1 = c10 + 2 * c20 * (I1 - 3), W2 = c01;
  Eigen::Matrix3d T = (W1 + I1 * W2) * Bbar - W2 * Bbar * Bbar;
  T -= T.trace() / 3 * Eigen::Matrix3d::Identity();
  return 2 / J * T + bulk * (J - 1) * Eigen::Matrix3d::Identity();
}

double lateralStretch(double l, PlaneHypothesis h, double c10, double c01, double c20, double bulk) {
  auto sigma22 = [&](double t) {
    Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
    F(0, 0) = l;
    F(1, 1) = t;
    if (h == PlaneHypothesis::PlaneStress) F(2, 2) = t;
    return handCauchy(F, c10, c01, c20, bulk)(1, 1);
  };
  double lo = 0.2, hi = 1.5;  // sigma_22 < 0 at lo, > 0 at hi
  EXPECT_LT(sigma22(lo), 0);
  EXPECT_GT(sigma22(hi), 0);
  for (int i = 0; i < 200 && hi - lo > 1e-16; ++i) (sigma22(0.5 * (lo + hi)) < 0 ? lo : hi) = 0.5 * (lo + hi);
  return 0.5 * (lo + hi);
}

// sigma = F S F^T / J of the law's PK2, F = [[F2, 0], [0, lambda3]].
Eigen::Matrix3d lawCauchy(const Eigen::Matrix2d& F2, double lambda3, const Eigen::Vector4d& S) {
  Eigen::Matrix3d F = Eigen::Matrix3d::Zero(), S3 = Eigen::Matrix3d::Zero();
  F.topLeftCorner<2, 2>() = F2;
  F(2, 2) = lambda3;
  S3 << S(0), S(3), 0, S(3), S(1), 0, 0, 0, S(2);
  return F * S3 * F.transpose() / F.determinant();
}

Eigen::Matrix2d greenLagrange(const Eigen::Matrix2d& F2) {
  return 0.5 * (F2.transpose() * F2 - Eigen::Matrix2d::Identity());
}

// Central differences of the law's stress along each Voigt strain (2 E12 for
// xy; E33 given to the law in D_PLAN, left to it in C_PLAN).
VoigtTangent differenceTangent(const Hyperelasticity& law, const Eigen::Matrix2d& E) {
  const double h = 1e-6;
  VoigtTangent D = VoigtTangent::Zero();
  for (int j : {kXX, kYY, kXY}) {
    Eigen::Matrix2d dE = Eigen::Matrix2d::Zero();
    if (j != kXY)
      dE(j, j) = h;
    else
      dE(0, 1) = dE(1, 0) = h / 2;
    D.col(j) = (run(law, E + dE, false).stress - run(law, E - dE, false).stress) / (2 * h);
  }
  if (law.hypothesis() == PlaneHypothesis::PlaneStrain)
    D.col(kZZ) = (run(law, E, false, h).stress - run(law, E, false, -h).stress) / (2 * h);
  return D;
}

std::vector<Eigen::Matrix2d> strainStates() {
  std::vector<Eigen::Matrix2d> states;
  Eigen::Matrix2d E;
  E << 0.01, 0.004, 0.004, -0.02;
  states.push_back(E);
  E << 0.4, -0.15, -0.15, 0.1;  // large strain
  states.push_back(E);
  E << -0.2, 0.3, 0.3, 0.6;
  states.push_back(E);
  E << -0.3, 0.0, 0.0, -0.25;  // compression
  states.push_back(E);
  return states;
}

}  // namespace

TEST(Hyperelasticity, TangentMatchesDifferencesOfTheStress) {
  for (auto h : {PlaneHypothesis::PlaneStrain, PlaneHypothesis::PlaneStress})
    for (double c20 : {0.0, kC20}) {
      const Hyperelasticity law(kC10, kC01, c20, kBulk, h);
      for (const auto& E : strainStates()) {
        SCOPED_TRACE(std::string(planeHypothesisName(h)) + " C20 " + std::to_string(c20) + " E11 " +
                     std::to_string(E(0, 0)));
        const Result r = run(law, E);
        const VoigtTangent fd = differenceTangent(law, E);
        // C_PLAN: the stress differences include the re-solved E33, so they give the condensed tangent.
        EXPECT_LT((r.tangent - fd).norm(), 1e-6 * r.tangent.norm());
        EXPECT_LT((r.tangent - r.tangent.transpose()).norm(), 1e-13 * r.tangent.norm());
        if (h == PlaneHypothesis::PlaneStress) {
          EXPECT_EQ(r.tangent.row(kZZ).norm(), 0.0);
          EXPECT_EQ(r.tangent.col(kZZ).norm(), 0.0);
        }
      }
    }
}

// Simple shear x += gamma y (J = 1, no volumetric stress), by hand from the
// header's formula with B = [[1 + g^2, g, 0], [g, 1, 0], [0, 0, 1]], I1 = I2 = 3 + g^2:
//   s12 = 2 g (W1 + W2),  s11 = 2 g^2 (2 W1 + W2) / 3,  s22 = -2 g^2 (W1 + 2 W2) / 3,
//   s33 = 2 g^2 (W2 - W1) / 3,  W1 = C10 + 2 C20 g^2, W2 = C01.
// For Mooney-Rivlin (C20 = 0) the shear response is linear: s12 = 2 (C10 + C01) g.
TEST(Hyperelasticity, SimpleShearByHand) {
  const Hyperelasticity law(kC10, kC01, kC20, kBulk, PlaneHypothesis::PlaneStrain);
  for (double g : {0.01, 0.3, 1.0, -0.8}) {
    SCOPED_TRACE("gamma " + std::to_string(g));
    Eigen::Matrix2d F;
    F << 1, g, 0, 1;
    const Eigen::Matrix3d sigma = lawCauchy(F, 1.0, run(law, greenLagrange(F), false).stress);
    const double W1 = kC10 + 2 * kC20 * g * g, W2 = kC01, tol = 1e-13 * (kC10 + kC01);
    EXPECT_NEAR(sigma(0, 1), 2 * g * (W1 + W2), tol);
    EXPECT_NEAR(sigma(0, 0), 2 * g * g * (2 * W1 + W2) / 3, tol);
    EXPECT_NEAR(sigma(1, 1), -2 * g * g * (W1 + 2 * W2) / 3, tol);
    EXPECT_NEAR(sigma(2, 2), 2 * g * g * (W2 - W1) / 3, tol);
  }
  const Hyperelasticity mooney(kC10, kC01, 0.0, kBulk, PlaneHypothesis::PlaneStrain);
  Eigen::Matrix2d F;
  F << 1, 0.9, 0, 1;
  EXPECT_NEAR(lawCauchy(F, 1.0, run(mooney, greenLagrange(F), false).stress)(0, 1), 2 * (kC10 + kC01) * 0.9, 1e-13);
}

// D_PLAN plane strain extension / compression F = diag(l1, l2, 1), compressible
// (J = l1 l2 != 1): in principal stretches the formula gives, I1 and I2 those of B,
//   sigma_i = (2/J) [W1 J^(-2/3) (l_i^2 - I1/3) + W2 J^(-4/3) (I1 l_i^2 - l_i^4 - 2 I2/3)] + K (J - 1).
TEST(Hyperelasticity, PlaneStrainStretchByHand) {
  const Hyperelasticity law(kC10, kC01, kC20, kBulk, PlaneHypothesis::PlaneStrain);
  for (auto [l1, l2] : {std::pair{1.3, 0.9}, std::pair{0.7, 1.05}, std::pair{2.0, 1.0}, std::pair{1.0, 1.0}}) {
    SCOPED_TRACE(std::to_string(l1) + " " + std::to_string(l2));
    const double J = l1 * l2, l[3] = {l1, l2, 1.0};
    const double I1 = l1 * l1 + l2 * l2 + 1, I2 = l1 * l1 * l2 * l2 + l1 * l1 + l2 * l2;
    const double W1 = kC10 + 2 * kC20 * (std::pow(J, -2.0 / 3.0) * I1 - 3), W2 = kC01;
    Eigen::Matrix2d F = Eigen::Matrix2d::Zero();
    F(0, 0) = l1;
    F(1, 1) = l2;
    const Eigen::Matrix3d sigma = lawCauchy(F, 1.0, run(law, greenLagrange(F), false).stress);
    for (int i = 0; i < 3; ++i) {
      const double li2 = l[i] * l[i];
      const double expected = 2 / J *
                                  (W1 * std::pow(J, -2.0 / 3.0) * (li2 - I1 / 3) +
                                   W2 * std::pow(J, -4.0 / 3.0) * (I1 * li2 - li2 * li2 - 2 * I2 / 3)) +
                              kBulk * (J - 1);
      EXPECT_NEAR(sigma(i, i), expected, 1e-12 * kBulk) << "component " << i;
    }
    EXPECT_NEAR(sigma(0, 1), 0.0, 1e-14);
    // The same by the tensor form of the formula (a check of the principal form above).
    Eigen::Matrix3d F3 = Eigen::Matrix3d::Identity();
    F3(0, 0) = l1;
    F3(1, 1) = l2;
    EXPECT_LT((sigma - handCauchy(F3, kC10, kC01, kC20, kBulk)).norm(), 1e-12 * kBulk);
  }
}

// C_PLAN uniaxial tension F = diag(l, t, t): the lateral stretch t solves
// sigma_22 = sigma_33 = 0 of the hand formula (bisection); the law, given E11 and
// E22, must find E33 = (t^2 - 1)/2 and give sigma_22 = 0 and the hand sigma_11.
TEST(Hyperelasticity, PlaneStressUniaxialTensionByHand) {
  for (double bulk : {kBulk, 1000.0}) {  // compressible and nearly incompressible
    const Hyperelasticity law(kC10, kC01, kC20, bulk, PlaneHypothesis::PlaneStress);
    for (double l : {1.05, 1.5, 2.5, 0.8}) {
      SCOPED_TRACE("K " + std::to_string(bulk) + " stretch " + std::to_string(l));
      const double t = lateralStretch(l, PlaneHypothesis::PlaneStress, kC10, kC01, kC20, bulk);
      Eigen::Matrix3d F3 = Eigen::Matrix3d::Identity();
      F3(0, 0) = l;
      F3(1, 1) = F3(2, 2) = t;
      Eigen::Matrix2d F = Eigen::Matrix2d::Zero();
      F(0, 0) = l;
      F(1, 1) = t;
      const Result r = run(law, greenLagrange(F), false);
      EXPECT_NEAR(r.strainZZ, 0.5 * (t * t - 1), 1e-12);
      const Eigen::Matrix3d sigma = lawCauchy(F, std::sqrt(1 + 2 * r.strainZZ), r.stress);
      const double s11 = handCauchy(F3, kC10, kC01, kC20, bulk)(0, 0);
      EXPECT_NEAR(sigma(0, 0), s11, 1e-10 * std::fabs(s11));
      EXPECT_NEAR(sigma(1, 1), 0.0, 1e-10 * std::fabs(s11));
      EXPECT_EQ(r.stress(kZZ), 0.0);
    }
  }
}

// C_PLAN: S33 = 0 at the E33 the law reports, evaluated by the same energy in
// D_PLAN form given that E33 (the law reads strainZZ there, as ELAS does), and
// the in-plane stresses agree. To 1e-12 of the in-plane stress, above the
// rounding floor of S33 itself: K (J - 1) with J - 1 known to a few ulps, eps K.
TEST(Hyperelasticity, PlaneStressZeroZZStress) {
  for (double c20 : {0.0, kC20})
    for (double bulk : {kBulk, 5000.0}) {
      const Hyperelasticity planeStress(kC10, kC01, c20, bulk, PlaneHypothesis::PlaneStress);
      const Hyperelasticity general(kC10, kC01, c20, bulk, PlaneHypothesis::PlaneStrain);
      std::mt19937 rng(3);
      std::uniform_real_distribution<double> uni(-0.3, 0.6);
      for (int trial = 0; trial < 50; ++trial) {
        Eigen::Matrix2d E;
        E << uni(rng), 0.5 * uni(rng), 0, uni(rng);
        E(1, 0) = E(0, 1);
        const Result r = run(planeStress, E, false);
        LawInput in;
        in.strain = E;
        in.strainZZ = r.strainZZ;
        LawOutput<VoigtTangent> out;
        general.integrate(in, out, false);
        const double scale = out.stress.cwiseAbs().maxCoeff();
        EXPECT_LE(std::fabs(out.stressZZ), 1e-12 * scale + 10 * std::numeric_limits<double>::epsilon() * bulk)
            << "trial " << trial;
        EXPECT_LT((out.stress - Eigen::Matrix2d{{r.stress(0), r.stress(3)}, {r.stress(3), r.stress(1)}}).norm(),
                  1e-12 * scale);
      }
    }
}

// At E = 0 the tangent is ELAS's with mu = 2 (C10 + C01) and the bulk K:
// E = 9 K mu / (3 K + mu), nu = (3 K - 2 mu) / (2 (3 K + mu)); C20 plays no part.
TEST(Hyperelasticity, SmallStrainLimitIsIsotropicElasticity) {
  const double mu = 2 * (kC10 + kC01);
  const double young = 9 * kBulk * mu / (3 * kBulk + mu), nu = (3 * kBulk - 2 * mu) / (2 * (3 * kBulk + mu));
  for (auto h : {PlaneHypothesis::PlaneStrain, PlaneHypothesis::PlaneStress}) {
    SCOPED_TRACE(planeHypothesisName(h));
    const Hyperelasticity law(kC10, kC01, kC20, kBulk, h);
    const Result r = run(law, Eigen::Matrix2d::Zero());
    const IsotropicElasticity elastic(young, nu, h);
    EXPECT_LT((r.tangent - elastic.voigt()).norm(), 1e-13 * elastic.voigt().norm());
    EXPECT_LT(r.stress.norm(), 1e-14);
    EXPECT_EQ(r.strainZZ, 0.0);
  }
}

TEST(Hyperelasticity, BulkFromPoissonGivesTheSmallStrainPoissonRatio) {
  // code_aster: K = 4 (C10 + C01) (1 + NU) / (3 (1 - 2 NU)), i.e. K = 2 mu (1 + NU) / (3 (1 - 2 NU)).
  const double nu = 0.3, K = Hyperelasticity::bulkFromPoisson(kC10, kC01, nu);
  EXPECT_NEAR(K, 4 * 0.9 * 1.3 / (3 * 0.4), 1e-14);
  const double mu = 2 * (kC10 + kC01);
  EXPECT_NEAR((3 * K - 2 * mu) / (2 * (3 * K + mu)), nu, 1e-14);
  EXPECT_THROW(Hyperelasticity::bulkFromPoisson(kC10, kC01, 0.5), Error);
  EXPECT_THROW(Hyperelasticity::bulkFromPoisson(kC10, kC01, -1.0), Error);
}

TEST(Hyperelasticity, RejectsBadDataAxisAndInvertedStates) {
  EXPECT_THROW(Hyperelasticity(kC10, kC01, kC20, kBulk, PlaneHypothesis::Axisymmetric), Error);
  EXPECT_THROW(Hyperelasticity(0.0, 0.0, kC20, kBulk, PlaneHypothesis::PlaneStrain), Error);
  EXPECT_THROW(Hyperelasticity(kC10, kC01, kC20, 0.0, PlaneHypothesis::PlaneStrain), Error);
  EXPECT_THROW(Hyperelasticity(kC10, kC01, kC20, -1.0, PlaneHypothesis::PlaneStress), Error);
  for (auto h : {PlaneHypothesis::PlaneStrain, PlaneHypothesis::PlaneStress}) {
    const Hyperelasticity law(kC10, kC01, kC20, kBulk, h);
    EXPECT_EQ(law.internalVariableCount(), 1);
    EXPECT_EQ(law.internalVariableNames(), std::vector<std::string>{"VIDE"});
    Eigen::Matrix2d E;
    E << -0.5, 0, 0, 0.2;  // C11 = 0: det C = 0
    EXPECT_THROW(run(law, E), Error);
    E << 0.5, 1.2, 1.2, 0.5;  // C = [[2, 2.4], [2.4, 2]]: det < 0
    EXPECT_THROW(run(law, E), Error);
  }
}

// Through a GROT_GDEP QUAD4 of the generic (virtual law) element path: the
// stiffness against central differences of the internal force, and rigid motions
// stress free.
TEST(Hyperelasticity, ElementTangentMatchesDifferences) {
  using Element = PlaneElement<CellType::QUAD4, BehaviourLaw>;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> uni(-1, 1);
  for (auto h : {PlaneHypothesis::PlaneStrain, PlaneHypothesis::PlaneStress})
    for (int trial = 0; trial < 3; ++trial) {
      SCOPED_TRACE(std::string(planeHypothesisName(h)) + " trial " + std::to_string(trial));
      const auto X = distortedCell<CellType::QUAD4>(60 + trial);
      const Element element(Hyperelasticity(kC10, kC01, kC20, kBulk, h), Kinematics::GreenLagrange);
      Element::Vector u;
      for (int i = 0; i < Element::dofs; ++i) u(i) = 0.12 * uni(rng);
      Element::Vector f;
      Element::Matrix K;
      element.internalForce(X, u, &f, &K);
      EXPECT_LT((K - testing_support::differenceTangent(element, X, u)).norm(), 1e-6 * K.norm());
      EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
    }
  const auto X = distortedCell<CellType::QUAD4>(5);
  const double theta = 0.9;
  Eigen::Matrix2d R;
  R << std::cos(theta), -std::sin(theta), std::sin(theta), std::cos(theta);
  Element::Vector u, f;
  for (int a = 0; a < Element::nodes; ++a)
    u.segment<2>(2 * a) = (R - Eigen::Matrix2d::Identity()) * X.row(a).transpose() + Eigen::Vector2d(0.3, -1.1);
  for (auto h : {PlaneHypothesis::PlaneStrain, PlaneHypothesis::PlaneStress}) {
    const Element element(Hyperelasticity(kC10, kC01, kC20, kBulk, h), Kinematics::GreenLagrange);
    element.internalForce(X, u, &f, nullptr);
    EXPECT_LT(f.norm(), 1e-12);
  }
}

// Unit square of QUAD4, GROT_GDEP, through MechanicalSystem and the Newton driver:
// DX = 0 on GAUCHE, DY = 0 on BAS, DX = d INST on DROITE, HAUT free. The state is
// homogeneous, F = diag(l, t, t3) with l = 1 + d INST, t from sigma_22 = 0 by hand
// (lateralStretch), t3 = t in C_PLAN, 1 in D_PLAN: uy = (t - 1) y, the Cauchy
// stresses of the hand formula (SIEF_ELGA), the reaction on DROITE the first
// Piola-Kirchhoff P11 = J sigma_11 / l on the unit reference side, VIDE = 0.
TEST(Hyperelasticity, UniaxialStretchThroughTheNewtonDriver) {
  for (auto h : {PlaneHypothesis::PlaneStrain, PlaneHypothesis::PlaneStress}) {
    SCOPED_TRACE(planeHypothesisName(h));
    auto mesh = std::make_shared<mesh::Mesh>(test_support::squareMesh(2, mesh::CellType::QUAD4));
    auto model = std::make_shared<model::Model>(mesh);
    std::vector<int> all(mesh->cellCount());
    for (int c = 0; c < mesh->cellCount(); ++c) all[c] = c;
    model->assign(all, h);
    const double d = 0.8;
    model::MechanicalLoad load;
    load.imposed.push_back({mesh->nodesOfCells(mesh->cellGroup("GAUCHE")), 0, model::SpaceFunction(0.0)});
    load.imposed.push_back({mesh->nodesOfCells(mesh->cellGroup("BAS")), 1, model::SpaceFunction(0.0)});
    load.imposed.push_back({mesh->nodesOfCells(mesh->cellGroup("DROITE")), 0, model::SpaceFunction(d)});
    auto multiplier = expr::Expression::compile("INST", {"INST"});

    analysis::MechanicalProblem problem;
    problem.model = model;
    problem.loads.push_back({&load, multiplier});
    problem.kinematics.assign(model->cells().size(), Kinematics::GreenLagrange);
    problem.relations.assign(model->cells().size(), std::make_shared<Hyperelasticity>(kC10, kC01, kC20, kBulk, h));
    analysis::MechanicalSystem system(problem);
    EXPECT_EQ(system.internalVariableCount(), 1);

    analysis::NewtonSettings settings;
    settings.resiGlobRela = 1e-12;
    settings.iterGlobMaxi = 20;
    analysis::StaticNonlinear newton(system, nullptr, settings);
    Eigen::VectorXd U = Eigen::VectorXd::Zero(newton.unknownCount());
    int instants = 0;
    newton.run(U, {0.0, 0.25, 0.5, 0.75, 1.0}, [&](const analysis::ConvergedInstant& c) {
      SCOPED_TRACE("INST " + std::to_string(c.time));
      const double l = 1 + d * c.time, t = lateralStretch(l, h, kC10, kC01, kC20, kBulk);
      const double t3 = h == PlaneHypothesis::PlaneStress ? t : 1.0;
      Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
      F(0, 0) = l;
      F(1, 1) = t;
      F(2, 2) = t3;
      const Eigen::Matrix3d sigma = handCauchy(F, kC10, kC01, kC20, kBulk);
      const double scale = std::fabs(sigma(0, 0));
      for (int n = 0; n < mesh->nodeCount(); ++n) {
        const Eigen::Vector3d x = mesh->node(n);
        EXPECT_NEAR((*c.U)(system.dof(n, 0)), (l - 1) * x(0), 1e-11);
        EXPECT_NEAR((*c.U)(system.dof(n, 1)), (t - 1) * x(1), 1e-11);
      }
      std::vector<int> offsets;
      std::vector<double> s;
      system.gaussStresses(*c.U, offsets, s);
      for (std::size_t q = 0; q < s.size() / 4; ++q) {
        EXPECT_NEAR(s[4 * q + 0], sigma(0, 0), 1e-10 * scale);
        EXPECT_NEAR(s[4 * q + 1], 0.0, 1e-10 * scale);
        EXPECT_NEAR(s[4 * q + 2], h == PlaneHypothesis::PlaneStress ? 0.0 : sigma(2, 2), 1e-10 * scale);
        EXPECT_NEAR(s[4 * q + 3], 0.0, 1e-10 * scale);
      }
      double reaction = 0;
      for (int n : mesh->nodesOfCells(mesh->cellGroup("DROITE"))) reaction += (*c.internalForces)(system.dof(n, 0));
      EXPECT_NEAR(reaction, F.determinant() * sigma(0, 0) / l, 1e-10 * scale);
      system.gaussVariables(offsets, s);
      for (double v : s) EXPECT_EQ(v, 0.0);
      ++instants;
    });
    EXPECT_EQ(instants, 4);
  }
}
