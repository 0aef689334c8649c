// Contact patch tests through the whole solver: an elastic block (small strain,
// E = 1, NU = 0.3) lying on a flat rigid master y = 0, pressed by a uniform
// pressure p on its top, sides free (DX held on GAUCHE only): the exact state
// is uniform, sigma_yy = -p, so the contact pressure must be -p everywhere
// and the slave must not penetrate; with matching and non-matching master
// segments, SEG2 and SEG3, DISCRETE and CONTINUE. Then the block lifted off:
// no contact left, zero pressure.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "../support/square_mesh.hpp"
#include "solver/contact_terms.hpp"
#include "solver/static_nonlinear.hpp"

using namespace aster;

namespace {

constexpr double kP = 0.01;

struct Case {
  mesh::CellType cell;  // QUAD4 (SEG2 edges) or QUAD8 (SEG3 edges)
  int masterSegments;   // 4 with N = 4: matching; 3: non-matching
  bool continueFormulation;
  const char* name;
};

struct Outcome {
  std::vector<double> gaps;          // at the slave nodes
  std::vector<double> pressures;     // LAGS_C at slave vertex nodes (CONTINUE)
  double multiplierSum = 0;          // DISCRETE: sum of nodal multipliers
  std::vector<mesh::NodalField> fields;
};

Outcome solve(const Case& c, bool liftOff) {
  const int N = 4;
  auto m = std::make_shared<mesh::Mesh>(test_support::squareMesh(N, c.cell));
  const bool quadratic = c.cell == mesh::CellType::QUAD8;
  // The master: y = 0 from x = -0.5 to 1.5, oriented from right to left so that
  // its normal (dy, -dx) points up, towards the block.
  std::vector<int> master;
  const double x0 = 1.5, x1 = -0.5;
  int prev = m->addNode(Eigen::Vector3d(x0, 0, 0));
  for (int s = 1; s <= c.masterSegments; ++s) {
    const double xa = x0 + (x1 - x0) * (s - 1) / c.masterSegments, xb = x0 + (x1 - x0) * s / c.masterSegments;
    const int next = m->addNode(Eigen::Vector3d(xb, 0, 0));
    if (quadratic)
      master.push_back(m->addCell(mesh::CellType::SEG3, {prev, next, m->addNode(Eigen::Vector3d(0.5 * (xa + xb), 0, 0))}));
    else
      master.push_back(m->addCell(mesh::CellType::SEG2, {prev, next}));
    prev = next;
  }
  m->addCellGroup("MAITRE", master);
  auto model = std::make_shared<model::Model>(m);
  std::vector<int> all(m->cellCount());
  for (int i = 0; i < m->cellCount(); ++i) all[i] = i;
  model->assign(all, model::Modelisation::PlaneStrain);
  auto material = std::make_shared<model::ElasticMaterial>();
  material->E = 1.0;
  material->NU = 0.3;
  auto materials = std::make_shared<model::MaterialField>(m->cellCount());
  materials->assign(all, material);

  model::MechanicalLoad load;
  load.imposed.push_back({m->nodesOfCells(master), 0, model::SpaceFunction(0.0)});
  load.imposed.push_back({m->nodesOfCells(master), 1, model::SpaceFunction(0.0)});
  load.imposed.push_back({m->nodesOfCells(m->cellGroup("GAUCHE")), 0, model::SpaceFunction(0.0)});
  if (liftOff)
    load.imposed.push_back({m->nodesOfCells(m->cellGroup("HAUT")), 1, model::SpaceFunction(0.02)});
  else
    load.edgeForces.push_back({m->cellGroup("HAUT"), model::SpaceFunction(0.0), model::SpaceFunction(-kP)});

  solver::MechanicalProblem problem;
  problem.model = model;
  problem.materials = materials;
  problem.loads.push_back({&load, nullptr});
  problem.kinematics.assign(model->cells().size(), mechanics::Kinematics::SmallStrain);
  solver::MechanicalSystem system(problem);
  solver::ContactSettings settings;
  settings.continueFormulation = c.continueFormulation;
  auto terms = solver::makeContactTerms(system, {{master, m->cellGroup("BAS")}}, settings);
  solver::NewtonSettings ns;
  ns.print = false;
  ns.resiGlobRela = 1e-12;
  ns.iterGlobMaxi = 30;
  solver::StaticNonlinear newton(system, terms.get(), ns);
  Eigen::VectorXd U = Eigen::VectorXd::Zero(newton.unknownCount());
  Outcome out;
  newton.run(U, {0.0, 1.0}, [&](const solver::ConvergedInstant& ci) {
    mesh::NodalField depl{"DEPL", {"DX", "DY"}, std::vector<double>(2 * m->nodeCount(), 0.0)};
    terms->extendDisplacement(*ci.U, depl);
    out.fields.push_back(depl);
    terms->outputFields(*ci.U, out.fields);
    for (int n : m->nodesOfCells(m->cellGroup("BAS"))) out.gaps.push_back((*ci.U)(system.dof(n, 1)));
    if (c.continueFormulation) {
      for (int n : m->nodesOfCells(m->cellGroup("BAS")))
        if (std::fabs(m->node(n)(0) * 2 * N - std::round(m->node(n)(0) * 2 * N)) < 1e-12 &&
            (!quadratic || std::lround(m->node(n)(0) * 2 * N) % 2 == 0))
          out.pressures.push_back(depl.values[3 * n + 2]);
    } else {
      for (int i = 0; i < terms->unknownCount(); ++i) out.multiplierSum += (*ci.U)(system.dofCount() + i);
    }
  });
  return out;
}

class ContactPatch : public ::testing::TestWithParam<Case> {};

TEST_P(ContactPatch, UniformPressureIsTransmittedExactly) {
  const Case c = GetParam();
  const Outcome o = solve(c, false);
  for (double g : o.gaps) EXPECT_NEAR(g, 0.0, 1e-10);  // the slave stays on y = 0: no penetration
  if (c.continueFormulation) {
    ASSERT_EQ(o.pressures.size(), 5u);
    for (double p : o.pressures) EXPECT_NEAR(p, -kP, 1e-10);
  } else {
    EXPECT_NEAR(o.multiplierSum, -kP * 1.0, 1e-10);  // the nodal forces add up to p times the width
  }
}

TEST_P(ContactPatch, BlockLiftedOffLeavesNoContact) {
  const Case c = GetParam();
  const Outcome o = solve(c, true);
  for (double g : o.gaps) EXPECT_GT(g, 0.0);
  if (c.continueFormulation)
    for (double p : o.pressures) EXPECT_NEAR(p, 0.0, 1e-12);
  else
    EXPECT_NEAR(o.multiplierSum, 0.0, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(
    Formulations, ContactPatch,
    ::testing::Values(Case{mesh::CellType::QUAD4, 4, false, "DISCRETE_SEG2_matching"},
                      Case{mesh::CellType::QUAD4, 3, false, "DISCRETE_SEG2_nonmatching"},
                      Case{mesh::CellType::QUAD8, 4, false, "DISCRETE_SEG3_matching"},
                      Case{mesh::CellType::QUAD8, 3, false, "DISCRETE_SEG3_nonmatching"},
                      Case{mesh::CellType::QUAD4, 4, true, "CONTINUE_SEG2_matching"},
                      Case{mesh::CellType::QUAD4, 3, true, "CONTINUE_SEG2_nonmatching"},
                      Case{mesh::CellType::QUAD8, 4, true, "CONTINUE_SEG3_matching"},
                      Case{mesh::CellType::QUAD8, 3, true, "CONTINUE_SEG3_nonmatching"}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
