// A behaviour law is one class: CubicVolumetricLaw below, written here and
// nowhere in src/, runs through the real element kernels, MechanicalSystem and
// the Newton driver. Checked: its tangent against finite differences (at the law
// and through the element), the generic (VoigtTangent) element path against the
// inlined isotropic one, and a homogeneous uniaxial test through StaticNonlinear
// against the closed-form solution, internal variables (VARI_ELGA) included.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

#include "../support/square_mesh.hpp"
#include "analysis/mechanical_system.hpp"
#include "analysis/static_nonlinear.hpp"
#include "expr/expression.hpp"
#include "mechanics/behaviour_law.hpp"
#include "mechanics/element_kernel.hpp"
#include "mechanics/isotropic_elasticity.hpp"
#include "patch_support.hpp"

using namespace aster;
using namespace aster::mechanics;
using namespace testing_support;

namespace {

// Plane strain hyperelasticity with the energy
//   W(e) = lambda/2 tr(e)^2 + beta/3 tr(e)^3 + mu e:e   (e_zz = 0),
// so s = (lambda tr + beta tr^2) I + 2 mu e, s_zz = lambda tr + beta tr^2 and
// dS/dE = (lambda + 2 beta tr) I x I + 2 mu I_sym (symmetric). Three internal
// variables that read the history: V1 the largest tr(e) of the accepted states,
// V2 the total variation of tr(e), sum |increment of tr(e)|, V3 the SIXX of the
// state the increment starts from (previous stress).
class CubicVolumetricLaw final : public BehaviourLaw {
 public:
  CubicVolumetricLaw(double lambda, double mu, double beta) : lambda_(lambda), mu_(mu), beta_(beta) {}
  PlaneHypothesis hypothesis() const override { return PlaneHypothesis::PlaneStrain; }
  int internalVariableCount() const override { return 3; }
  void integrate(const LawInput& in, LawOutput<VoigtTangent>& out, bool withTangent) const override {
    const double tr = in.strain.trace();
    const double p = lambda_ * tr + beta_ * tr * tr;
    out.stress = p * Eigen::Matrix2d::Identity() + 2 * mu_ * in.strain;
    out.stressZZ = p;
    out.variables[0] = std::max(in.previousVariables[0], tr);
    out.variables[1] = in.previousVariables[1] + std::fabs(in.strainIncrement.trace());
    out.variables[2] = in.previousStress[0];
    if (withTangent) {
      const double k = lambda_ + 2 * beta_ * tr;
      // (xx, yy, zz, 2 xy): s_zz = p depends on tr(e) = e_xx + e_yy only (e_zz = 0).
      out.tangent << k + 2 * mu_, k, 0, 0,  //
          k, k + 2 * mu_, 0, 0,             //
          k, k, 0, 0,                       //
          0, 0, 0, mu_;
    }
  }

 private:
  double lambda_, mu_, beta_;
};

constexpr double kLambda = 1.2, kMu = 0.8, kBeta = 15.0;

Eigen::Vector4d voigtStress(const Eigen::Matrix2d& s, double szz) { return {s(0, 0), s(1, 1), szz, s(0, 1)}; }

TEST(BehaviourLaw, CubicLawTangentMatchesDifferences) {
  const CubicVolumetricLaw law(kLambda, kMu, kBeta);
  const double previous[3] = {0, 0, 0}, stress0[4] = {0, 0, 0, 0};
  double variables[3];
  LawInput in;
  in.strain << 0.03, -0.02, -0.02, 0.05;
  in.strainIncrement = in.strain;
  in.previousStress = stress0;
  in.previousVariables = previous;
  LawOutput<VoigtTangent> out, plus, minus;
  out.variables = plus.variables = minus.variables = variables;
  law.integrate(in, out, true);
  const double h = 1e-7;
  for (int j : {kXX, kYY, kXY}) {
    // Voigt strains (E11, E22, E33, 2 E12): a step h in 2 E12 moves E12 and E21 by h/2.
    Eigen::Matrix2d dE = Eigen::Matrix2d::Zero();
    if (j != kXY) dE(j, j) = h;
    else dE(0, 1) = dE(1, 0) = h / 2;
    LawInput ip = in, im = in;
    ip.strain += dE;
    im.strain -= dE;
    law.integrate(ip, plus, false);
    law.integrate(im, minus, false);
    const Eigen::Vector4d column =
        (voigtStress(plus.stress, plus.stressZZ) - voigtStress(minus.stress, minus.stressZZ)) / (2 * h);
    EXPECT_LT((column - out.tangent.col(j)).norm(), 1e-7 * out.tangent.norm()) << "column " << j;
  }
}

template <CellType T>
void elementTangentMatchesDifferences() {
  using E = PlaneElement<T, BehaviourLaw>;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> uni(-1, 1);
  for (auto k : {Kinematics::SmallStrain, Kinematics::GreenLagrange}) {
    SCOPED_TRACE(std::string(fem::cellName(T)) + (k == Kinematics::SmallStrain ? " PETIT" : " GROT_GDEP"));
    const auto X = distortedCell<T>(40);
    const E element(CubicVolumetricLaw(kLambda, kMu, kBeta), k);
    EXPECT_EQ(element.build(), KernelBuild::Baseline);
    typename E::Vector u;
    for (int i = 0; i < E::dofs; ++i) u(i) = 0.1 * uni(rng);
    typename E::Vector f;
    typename E::Matrix K;
    element.internalForce(X, u, &f, &K);
    EXPECT_LT((K - differenceTangent(element, X, u)).norm(), 1e-6 * K.norm());
  }
}

TEST(BehaviourLaw, ElementTangentOfTheCubicLawMatchesDifferences) {
  elementTangentMatchesDifferences<CellType::TRIA3>();
  elementTangentMatchesDifferences<CellType::TRIA6>();
  elementTangentMatchesDifferences<CellType::QUAD4>();
  elementTangentMatchesDifferences<CellType::QUAD8>();
  elementTangentMatchesDifferences<CellType::QUAD9>();
}

// The generic element path (virtual law, VoigtTangent, B^T D B) and the inlined
// isotropic one (IsotropicTangent) are two derivations of the same f and K.
template <CellType T>
void genericPathMatchesInlinedElasticity() {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> uni(-1, 1);
  for (auto h : {PlaneHypothesis::PlaneStrain, PlaneHypothesis::PlaneStress})
    for (auto k : {Kinematics::SmallStrain, Kinematics::GreenLagrange}) {
      SCOPED_TRACE(fem::cellName(T));
      const IsotropicElasticity law(210.0, 0.3, h);
      const PlaneElement<T> inlined(law, k);
      const PlaneElement<T, BehaviourLaw> generic(law, k);
      const auto X = distortedCell<T>(7);
      typename PlaneElement<T>::Vector u, f1, f2;
      typename PlaneElement<T>::Matrix K1, K2;
      for (int i = 0; i < u.size(); ++i) u(i) = 0.1 * uni(rng);
      inlined.internalForce(X, u, &f1, &K1);
      generic.internalForce(X, u, &f2, &K2);
      EXPECT_LT((f1 - f2).norm(), 1e-13 * f1.norm());
      EXPECT_LT((K1 - K2).norm(), 1e-13 * K1.norm());
      std::vector<double> s1(4 * inlined.gaussPointCount()), s2(s1.size());
      inlined.gaussStresses(X, u, s1.data());
      generic.gaussStresses(X, u, s2.data());
      for (std::size_t i = 0; i < s1.size(); ++i) EXPECT_NEAR(s1[i], s2[i], 1e-13 * 210.0);
    }
}

TEST(BehaviourLaw, GenericElementPathMatchesInlinedElasticity) {
  genericPathMatchesInlinedElasticity<CellType::TRIA3>();
  genericPathMatchesInlinedElasticity<CellType::TRIA6>();
  genericPathMatchesInlinedElasticity<CellType::QUAD4>();
  genericPathMatchesInlinedElasticity<CellType::QUAD8>();
  genericPathMatchesInlinedElasticity<CellType::QUAD9>();
}

TEST(BehaviourLaw, KernelChoosesTheInlinedBuildForElasticityOnly) {
  const auto elastic = std::make_shared<IsotropicElasticity>(1.0, 0.3, PlaneHypothesis::PlaneStrain);
  const auto cubic = std::make_shared<CubicVolumetricLaw>(kLambda, kMu, kBeta);
  const auto a = makePlaneKernel(mesh::CellType::QUAD8, elastic, Kinematics::SmallStrain);
  const auto b = makePlaneKernel(mesh::CellType::QUAD8, cubic, Kinematics::SmallStrain);
  EXPECT_FALSE(a->usesHistory());
  EXPECT_EQ(a->internalVariables(), 0);
  EXPECT_TRUE(b->usesHistory());
  EXPECT_EQ(b->internalVariables(), 3);
  EXPECT_EQ(b->gaussPoints(), 9);
}

// Unit square, PETIT, plane strain: DX = 0 on GAUCHE, DY = 0 on BAS, DX = d(t) on
// DROITE, HAUT free. The state is homogeneous: e11 = d, e22 = e with s22 = 0:
//   lambda tr + beta tr^2 + 2 mu (tr - d) = 0, tr = d + e,
// a quadratic in tr solved by hand; then s11 = p + 2 mu d, s_zz = p, p = lambda tr + beta tr^2,
// and the reaction on DROITE is s11 * 1. Loading d = 0.05 at INST 1, unloading to
// 0.025 at INST 2: V1 = tr(1), V2 = tr(1) + (tr(1) - tr(2)), V3 = s11 at the
// instant before (0 at INST 1).
TEST(BehaviourLaw, CubicLawThroughTheNewtonDriverMatchesTheHomogeneousSolution) {
  auto mesh = std::make_shared<mesh::Mesh>(test_support::squareMesh(3, mesh::CellType::QUAD4));
  auto model = std::make_shared<model::Model>(mesh);
  std::vector<int> all(mesh->cellCount());
  for (int c = 0; c < mesh->cellCount(); ++c) all[c] = c;
  model->assign(all, model::Modelisation::PlaneStrain);
  const double d = 0.05;
  model::MechanicalLoad load;
  load.imposed.push_back({mesh->nodesOfCells(mesh->cellGroup("GAUCHE")), 0, model::SpaceFunction(0.0)});
  load.imposed.push_back({mesh->nodesOfCells(mesh->cellGroup("BAS")), 1, model::SpaceFunction(0.0)});
  load.imposed.push_back({mesh->nodesOfCells(mesh->cellGroup("DROITE")), 0, model::SpaceFunction(d)});
  // 1 at INST 1, 0.5 at INST 2.
  auto multiplier = expr::Expression::compile("INST * (1.75 - 0.75 * INST)", {"INST"});

  analysis::MechanicalProblem problem;
  problem.model = model;
  problem.loads.push_back({&load, multiplier});
  problem.kinematics.assign(model->cells().size(), Kinematics::SmallStrain);
  problem.relations.assign(model->cells().size(), std::make_shared<CubicVolumetricLaw>(kLambda, kMu, kBeta));
  analysis::MechanicalSystem system(problem);
  EXPECT_EQ(system.internalVariableCount(), 3);

  analysis::NewtonSettings settings;
  settings.resiGlobRela = 1e-12;
  analysis::StaticNonlinear newton(system, nullptr, settings);
  Eigen::VectorXd U = Eigen::VectorXd::Zero(newton.unknownCount());

  auto traceFor = [](double stretch) {
    const double b = kLambda + 2 * kMu;
    return (-b + std::sqrt(b * b + 8 * kBeta * kMu * stretch)) / (2 * kBeta);
  };
  const double tr1 = traceFor(d), tr2 = traceFor(0.5 * d);
  std::vector<double> traces;
  newton.run(U, {0.0, 1.0, 2.0}, [&](const analysis::ConvergedInstant& c) {
    const double stretch = c.time == 1.0 ? d : 0.5 * d;
    const double tr = traceFor(stretch);
    const double p = kLambda * tr + kBeta * tr * tr;
    // Displacements: uy = e * Y everywhere.
    for (int n = 0; n < mesh->nodeCount(); ++n) {
      const Eigen::Vector3d x = mesh->node(n);
      EXPECT_NEAR((*c.U)(system.dof(n, 0)), stretch * x(0), 1e-12);
      EXPECT_NEAR((*c.U)(system.dof(n, 1)), (tr - stretch) * x(1), 1e-12);
    }
    std::vector<int> offsets;
    std::vector<double> s;
    system.gaussStresses(*c.U, offsets, s);
    for (std::size_t q = 0; q < s.size() / 4; ++q) {
      EXPECT_NEAR(s[4 * q + 0], p + 2 * kMu * stretch, 1e-12);
      EXPECT_NEAR(s[4 * q + 1], 0.0, 1e-12);
      EXPECT_NEAR(s[4 * q + 2], p, 1e-12);
      EXPECT_NEAR(s[4 * q + 3], 0.0, 1e-12);
    }
    double reaction = 0;
    for (int n : mesh->nodesOfCells(mesh->cellGroup("DROITE"))) reaction += (*c.internalForces)(system.dof(n, 0));
    EXPECT_NEAR(reaction, p + 2 * kMu * stretch, 1e-12);
    system.gaussVariables(offsets, s);
    ASSERT_EQ(s.size(), 3 * 4 * model->cells().size());  // 3 variables, 4 points per QUAD4
    const double v1 = tr1, v2 = c.time == 1.0 ? tr1 : tr1 + (tr1 - tr2);
    const double v3 = c.time == 1.0 ? 0.0 : kLambda * tr1 + kBeta * tr1 * tr1 + 2 * kMu * d;
    for (std::size_t q = 0; q < s.size() / 3; ++q) {
      EXPECT_NEAR(s[3 * q], v1, 1e-12);
      EXPECT_NEAR(s[3 * q + 1], v2, 1e-12);
      EXPECT_NEAR(s[3 * q + 2], v3, 1e-12);
    }
    traces.push_back(tr);
  });
  EXPECT_EQ(traces.size(), 2u);
}

}  // namespace
