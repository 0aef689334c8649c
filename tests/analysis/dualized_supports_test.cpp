// The residual at the supports: code_aster measures it where AFFE_CHAR_MECA imposes a
// displacement (a Lagrange multiplier carries the reaction, updated by each linear solve)
// and not where AFFE_CHAR_CINE does (eliminated).
//
// One QUAD4 of the unit square in plane strain, Saint Venant-Kirchhoff (GROT_GDEP), E = 1,
// NU = 0; DX = 0 on GAUCHE, DY = 0 on BAS, DX = d on DROITE. The stretch l = 1 + d is
// uniform and the lateral one stays 1: the free unknowns (DY of HAUT) never carry a
// residual, and the first correction (from the tangent at rest, E) reaches the solution.
// The reaction on DROITE is P(l) = E l (l^2 - 1) / 2, P / 2 per node, whereas the solve
// predicted E d / 2: the multiplier is off by e = (P(l) - E d) / 2 = E (3 d^2 + d^3) / 4,
// and RESI_GLOB_RELA, relative to the largest reaction P / 2, is
//   (3 d + d^2) / ((1 + d) (2 + d)).
// So with DDL_IMPO code_aster iterates once more (a zero correction, the multiplier
// corrected, residual zero); with AFFE_CHAR_CINE the first iterate converges.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "stiffening_bar.hpp"

using namespace aster;

namespace {

std::vector<double> stretchResiduals(double d, bool kinematic) {
  const test_support::Bar bar = test_support::unitBar();
  const auto& m = bar.mesh;
  model::MechanicalLoad load;
  load.kinematic = kinematic;
  load.imposed.push_back({m->nodesOfCells(m->cellGroup("GAUCHE")), 0, model::SpaceFunction(0.0)});
  load.imposed.push_back({m->nodesOfCells(m->cellGroup("BAS")), 1, model::SpaceFunction(0.0)});
  load.imposed.push_back({m->nodesOfCells(m->cellGroup("DROITE")), 0, model::SpaceFunction(d)});
  analysis::MechanicalProblem problem;
  problem.model = bar.model;
  problem.materials = bar.materials;
  problem.loads.push_back({&load, nullptr});
  problem.kinematics.assign(bar.model->cells().size(), mechanics::Kinematics::GreenLagrange);
  analysis::MechanicalSystem system(problem);
  analysis::NewtonSettings settings;
  settings.resiGlobRela = 1e-6;
  analysis::StaticNonlinear newton(system, nullptr, settings);
  Eigen::VectorXd U = Eigen::VectorXd::Zero(newton.unknownCount());
  std::vector<double> residuals;
  newton.run(U, {0.0, 1.0}, [&](const analysis::ConvergedInstant& c) { residuals = c.residuals; });
  const int corner = m->nodesOfCells(m->cellGroup("DROITE")).front();
  EXPECT_NEAR(U(system.dof(corner, 0)), d, 1e-15);
  return residuals;
}

TEST(DualizedSupports, TheMultiplierOfAffeCharMecaIsCorrectedByOneMoreIteration) {
  const double d = 0.1;
  const std::vector<double> r = stretchResiduals(d, false);
  ASSERT_EQ(r.size(), 3u);  // the prediction's start, its iterate, the multiplier corrected
  EXPECT_NEAR(r[1], (3 * d + d * d) / ((1 + d) * (2 + d)), 1e-12);
  EXPECT_LE(r[2], 1e-14);
}

TEST(DualizedSupports, AffeCharCineIsNotMeasured) {
  const std::vector<double> r = stretchResiduals(0.1, true);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_LE(r[1], 1e-14);
}

}  // namespace
