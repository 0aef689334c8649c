// NORTON through MechanicalSystem and the Newton driver: a unit square in plane
// strain held at a constant stretch (DX = d on DROITE from the first instant)
// relaxes. The prediction of each step starts from the accepted state and, as
// code_aster's, balances that state's internal forces: with the stretch unchanged
// they are in equilibrium, so the residual of the prediction is the converged one
// of the step before (not the relaxation the law would give over the new step at
// the same displacement); the corrections then bring the relaxation in.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "../support/square_mesh.hpp"
#include "analysis/mechanical_system.hpp"
#include "analysis/newton_observer.hpp"
#include "analysis/static_nonlinear.hpp"
#include "expr/expression.hpp"
#include "mechanics/lemaitre_viscoplasticity.hpp"

using namespace aster;
using namespace aster::mechanics;

namespace {

struct FirstResiduals : analysis::NewtonObserver {
  std::vector<double> rela;  // per step: RESI_GLOB_RELA of its first iteration
  std::vector<int> iterations;
  void iterationDone(const analysis::NewtonIteration& it) override {
    if (it.index == 0) rela.push_back(it.rela);
  }
  void stepConverged(double, int n, bool) override { iterations.push_back(n); }
};

TEST(LemaitreDriver, ThePredictionBalancesTheAcceptedState) {
  auto mesh = std::make_shared<mesh::Mesh>(test_support::squareMesh(1, mesh::CellType::QUAD4));
  auto model = std::make_shared<model::Model>(mesh);
  std::vector<int> all(mesh->cellCount());
  for (int c = 0; c < mesh->cellCount(); ++c) all[c] = c;
  model->assign(all, model::Modelisation::PlaneStrain);
  const double d = 2e-3;
  model::MechanicalLoad load;
  load.imposed.push_back({mesh->nodesOfCells(mesh->cellGroup("GAUCHE")), 0, model::SpaceFunction(0.0)});
  load.imposed.push_back({mesh->nodesOfCells(mesh->cellGroup("BAS")), 1, model::SpaceFunction(0.0)});
  load.imposed.push_back({mesh->nodesOfCells(mesh->cellGroup("DROITE")), 0, model::SpaceFunction(d)});
  auto multiplier = expr::Expression::compile("1 + 0 * INST", {"INST"});

  LemaitreParameters parameters = nortonParameters(200e3, 0.3, 3, 1 / 100.0, 0, 1);
  auto law = std::make_shared<LemaitreViscoplasticity>(parameters, PlaneHypothesis::PlaneStrain);
  analysis::MechanicalProblem problem;
  problem.model = model;
  problem.loads.push_back({&load, multiplier});
  problem.kinematics.assign(model->cells().size(), Kinematics::SmallStrain);
  problem.relations.assign(model->cells().size(), law);
  analysis::MechanicalSystem system(problem);
  EXPECT_TRUE(system.predictsFromAcceptedState());

  analysis::NewtonSettings settings;
  settings.resiGlobRela = 1e-12;
  analysis::StaticNonlinear newton(system, nullptr, settings);
  FirstResiduals watch;
  newton.addObserver(watch);
  Eigen::VectorXd U = Eigen::VectorXd::Zero(newton.unknownCount());
  std::vector<double> sxx;
  newton.run(U, {0.0, 1e-5, 2e-5, 4e-5}, [&](const analysis::ConvergedInstant& c) {
    std::vector<int> offsets;
    std::vector<double> s;
    system.gaussStresses(*c.U, offsets, s);
    sxx.push_back(s[0]);
  });
  ASSERT_EQ(watch.rela.size(), watch.iterations.size());
  ASSERT_EQ(sxx.size(), 3u);
  // The stress relaxes, and needs corrections to do so.
  EXPECT_LT(sxx[1], 0.95 * sxx[0]);
  EXPECT_LT(sxx[2], 0.95 * sxx[1]);
  for (std::size_t k = 1; k < watch.rela.size(); ++k) {
    EXPECT_LE(watch.rela[k], 1e-10) << "step " << k;
    EXPECT_GE(watch.iterations[k], 2) << "step " << k;
  }
}

}  // namespace
