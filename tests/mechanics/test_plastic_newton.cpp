// The von Mises laws through the element kernels and the Newton driver: with the
// consistent tangent Newton converges quadratically once near the solution
// (asserted on the residual sequence of plastic steps), and in plane stress every
// Gauss point has s_zz = 0 to rounding. The problem: the unit square in QUAD8,
// DX = 0 on GAUCHE, DY = 0 on BAS, and on HAUT DY = d (1 + X) (a non-uniform
// stretch that yields the square unevenly), d rising over three steps.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "../support/square_mesh.hpp"
#include "analysis/mechanical_system.hpp"
#include "analysis/static_nonlinear.hpp"
#include "expr/expression.hpp"
#include "mechanics/von_mises_plasticity.hpp"

using namespace aster;
using namespace aster::mechanics;

namespace {

struct NewtonRun {
  std::vector<std::vector<double>> residuals;  // per step
  std::vector<double> maxStressZZ;             // per step: max |SIZZ| / max |stress|
  double maxPlasticStrain = 0;
};

NewtonRun solve(const VonMisesParameters& parameters, PlaneHypothesis hypothesis, Kinematics kinematics) {
  auto mesh = std::make_shared<mesh::Mesh>(test_support::squareMesh(4, mesh::CellType::QUAD8));
  auto model = std::make_shared<model::Model>(mesh);
  std::vector<int> all(mesh->cellCount());
  for (int c = 0; c < mesh->cellCount(); ++c) all[c] = c;
  model->assign(all, hypothesis == PlaneHypothesis::PlaneStress ? model::Modelisation::PlaneStress
                                                                : model::Modelisation::PlaneStrain);
  model::MechanicalLoad load;
  load.imposed.push_back({mesh->nodesOfCells(mesh->cellGroup("GAUCHE")), 0, model::SpaceFunction(0.0)});
  load.imposed.push_back({mesh->nodesOfCells(mesh->cellGroup("BAS")), 1, model::SpaceFunction(0.0)});
  load.imposed.push_back({mesh->nodesOfCells(mesh->cellGroup("HAUT")), 1,
                          model::SpaceFunction(expr::Expression::compile("0.004 * INST * (1 + X)", {"X", "INST"}))});
  analysis::MechanicalProblem problem;
  problem.model = model;
  problem.loads.push_back({&load, nullptr});
  problem.kinematics.assign(model->cells().size(), kinematics);
  problem.relations.assign(model->cells().size(), std::make_shared<VonMisesPlasticity>(parameters, hypothesis));
  analysis::MechanicalSystem system(problem);
  analysis::NewtonSettings settings;
  settings.resiGlobRela = 1e-13;
  settings.iterGlobMaxi = 20;
  analysis::StaticNonlinear newton(system, nullptr, settings);
  Eigen::VectorXd U = Eigen::VectorXd::Zero(newton.unknownCount());
  NewtonRun result;
  newton.run(U, {0.0, 1.0, 2.0, 3.0}, [&](const analysis::ConvergedInstant& c) {
    result.residuals.push_back(c.residuals);
    std::vector<int> offsets;
    std::vector<double> s;
    system.gaussStresses(*c.U, offsets, s);
    double zz = 0, scale = 0;
    for (std::size_t q = 0; q < s.size() / 4; ++q) {
      zz = std::max(zz, std::fabs(s[4 * q + 2]));
      for (int i = 0; i < 4; ++i) scale = std::max(scale, std::fabs(s[4 * q + i]));
    }
    result.maxStressZZ.push_back(zz / scale);
    system.gaussVariables(offsets, s);
    const int epspeq = parameters.variables == VonMisesVariables::Kinematic ? 7 : 0;
    const int count = system.internalVariableCount();
    for (std::size_t q = 0; q < s.size() / count; ++q)
      result.maxPlasticStrain = std::max(result.maxPlasticStrain, s[q * count + epspeq]);
  });
  return result;
}

// Quadratic convergence: once the relative residual is below 1e-3, each next one is
// at most a modest multiple of its square (until rounding, 1e-12, takes over). The
// first residual of a step is the last instant's (the imposed displacements of the
// step enter with the first correction): the sequence starts at the second.
void expectQuadratic(const NewtonRun& r) {
  int checked = 0;
  for (const auto& seq : r.residuals) {
    ASSERT_GE(seq.size(), 2u);
    for (std::size_t k = 1; k + 1 < seq.size(); ++k) {
      if (seq[k] > 1e-3 || seq[k + 1] < 1e-12) continue;
      EXPECT_LE(seq[k + 1], 1e3 * seq[k] * seq[k]) << "iteration " << k + 1 << ": " << seq[k] << " -> " << seq[k + 1];
      ++checked;

    }
  }
  EXPECT_GE(checked, 2) << "no iteration in the quadratic range";
}

constexpr double kE = 200e3, kNu = 0.3, kSy = 200, kEt = 20e3;

TEST(PlasticNewton, QuadraticConvergenceWithTheConsistentTangent) {
  for (auto kinematics : {Kinematics::SmallStrain, Kinematics::GreenLagrange, Kinematics::Logarithmic})
    for (auto hypothesis : {PlaneHypothesis::PlaneStrain, PlaneHypothesis::PlaneStress})
      for (const auto& parameters : {isotropicLinearParameters(kE, kNu, kEt, kSy),
                                     kinematicLinearParameters(kE, kNu, kEt, kSy),
                                     mixedLinearParameters(kE, kNu, kEt, kSy, 5e3)}) {
        SCOPED_TRACE(std::string(planeHypothesisName(hypothesis)) +
                     (kinematics == Kinematics::SmallStrain     ? " PETIT"
                      : kinematics == Kinematics::GreenLagrange ? " GROT_GDEP"
                                                                : " GDEF_LOG"));
        const NewtonRun r = solve(parameters, hypothesis, kinematics);
        ASSERT_EQ(r.residuals.size(), 3u);
        EXPECT_GT(r.maxPlasticStrain, 1e-3);  // well into the plastic range
        expectQuadratic(r);
        if (hypothesis == PlaneHypothesis::PlaneStress) {
          for (double zz : r.maxStressZZ) EXPECT_LE(zz, 1e-12);
        }
      }
}

}  // namespace
