// Contact patch tests through the whole solver (mechanical system, contact
// terms, Newton), against solutions derived by hand.
//
// A block [0,1]^2 (E = 1, NU = 0.3, N x N QUAD4 or QUAD8 cells) lies on a flat
// rigid master y = y0 (SEG2 or SEG3 cells, walked right to left so that their
// normal points up); DX is held on GAUCHE, the sides are free.
//
// Pressed by a uniform dead traction (0, -p) on HAUT, the exact solution is
// homogeneous: x = l1 X, y = l2 Y + s, with the nominal stress P22 = -p, P11 =
// 0, and the contact pressure (nominal, per unit reference length) is -p at
// every slave point. The finite elements reproduce it exactly, so every slave
// node must show RN = -p, JEU = 0 and the nodal force RNY = p A_i (A_i = int
// N_i over BAS: h/2 and h at the ends and inside for SEG2, h/6 per cell at the
// vertices and 2h/3 at the middle nodes for SEG3), to round-off.
//   small strain, D_PLAN: l2 - 1 = -(1 - NU^2) p / E, l1 - 1 = NU (1 + NU) p / E;
//   small strain, C_PLAN: l2 - 1 = -p / E,            l1 - 1 = NU p / E;
//   Saint Venant-Kirchhoff (GROT_GDEP), D_PLAN: with E_ij = (l_i^2 - 1) / 2,
//     S11 = 0 gives E11 = -NU / (1 - NU) E22, then S22 = E / (1 - NU^2) E22
//     and P22 = l2 S22 = -p: the cubic E / (1 - NU^2) l2 (l2^2 - 1) / 2 = -p.
//   s = 0 with the exact constraints; s = -p / k with penalisation (coefficient
//   k: every node penetrates by p / k, RN = k JEU = -p).
// Slave and master are subdivided alike (matching) or not: 3 slave cells on 2
// master cells spanning exactly [0, 1], a master of one long segment, a master
// overhanging the block.
//
// Lifted by DY = 0.02 on HAUT: a rigid translation, no contact left (empty
// active set), zero pressure and force, JEU = 0.02.
// Pushed by DY = -0.2 on HAUT onto a master 0.1 below: uniform strain
// eps_yy = -0.1, contact pressure E / (1 - NU^2) eps_yy (sides free); with
// DIST_APPA = 0.05 the slave is never paired and the block just translates.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <regex>
#include <string>

#include "../support/square_mesh.hpp"
#include "analysis/contact_terms.hpp"
#include "analysis/convergence_table.hpp"
#include "analysis/static_nonlinear.hpp"

using namespace aster;

namespace {

constexpr double kE = 1.0, kNu = 0.3;

enum class Load { Press, Lift, PushDown };

struct Case {
  std::string name;
  mesh::CellType cell = mesh::CellType::QUAD4;  // QUAD4: SEG2 edges, QUAD8: SEG3 edges
  int N = 4;                                     // N x N cells, N slave cells along BAS
  int masterSegments = 4;
  double masterRight = 1.5, masterLeft = -0.5;
  bool continueFormulation = false;
  model::Modelisation modelisation = model::Modelisation::PlaneStrain;
  mechanics::Kinematics kinematics = mechanics::Kinematics::SmallStrain;
  double penalty = 0;  // E_N or COEF_PENA_CONT (0: CONTRAINTE / STANDARD)
  double p = 0.01;
};

// gtest prints a case by its name (not its bytes).
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

struct Outcome {
  std::shared_ptr<mesh::Mesh> mesh;
  mesh::NodalField depl, cont;  // DEPL (with LAGS_C for CONTINUE), CONT_NOEU
  std::string status;           // statusText() at the converged state
  std::string table;            // the convergence table (when printed)
  int iterations = 0;
  std::vector<int> slave;       // the nodes of BAS
  int blockNodes = 0;           // nodes 0 .. blockNodes-1 are the block's (then the master's)
};

double at(const mesh::NodalField& f, int node, const std::string& cmp) {
  for (std::size_t c = 0; c < f.components.size(); ++c)
    if (f.components[c] == cmp) return f.values[node * f.components.size() + c];
  ADD_FAILURE() << f.name << " has no component " << cmp;
  return NAN;
}

// The number after "residual " in a status text.
double residualOf(const std::string& status) {
  std::smatch m;
  if (!std::regex_search(status, m, std::regex("residual ([0-9.E+-]+)"))) return NAN;
  return std::stod(m[1]);
}

Outcome solve(const Case& c, Load loading, analysis::ZoneSettings zone = {}, double y0 = 0.0,
              bool cornerHeld = false, bool print = false) {
  auto m = std::make_shared<mesh::Mesh>(test_support::squareMesh(c.N, c.cell));
  const bool quadratic = c.cell == mesh::CellType::QUAD8;
  std::vector<int> master;
  int prev = m->addNode(Eigen::Vector3d(c.masterRight, y0, 0));
  for (int s = 1; s <= c.masterSegments; ++s) {
    const double xa = c.masterRight + (c.masterLeft - c.masterRight) * (s - 1) / c.masterSegments;
    const double xb = c.masterRight + (c.masterLeft - c.masterRight) * s / c.masterSegments;
    const int next = m->addNode(Eigen::Vector3d(xb, y0, 0));
    if (quadratic)
      master.push_back(m->addCell(mesh::CellType::SEG3, {prev, next, m->addNode(Eigen::Vector3d(0.5 * (xa + xb), y0, 0))}));
    else
      master.push_back(m->addCell(mesh::CellType::SEG2, {prev, next}));
    prev = next;
  }
  m->addCellGroup("MAITRE", master);
  auto model = std::make_shared<model::Model>(m);
  std::vector<int> all(m->cellCount());
  for (int i = 0; i < m->cellCount(); ++i) all[i] = i;
  model->assign(all, c.modelisation);
  auto material = std::make_shared<model::ElasticMaterial>();
  material->E = kE;
  material->NU = kNu;
  auto materials = std::make_shared<model::MaterialField>(m->cellCount());
  materials->assign(all, material);

  Outcome out;
  out.mesh = m;
  out.blockNodes = test_support::squareMesh(c.N, c.cell).nodeCount();
  out.slave = m->nodesOfCells(m->cellGroup("BAS"));
  model::MechanicalLoad load;
  load.imposed.push_back({m->nodesOfCells(master), 0, model::SpaceFunction(0.0)});
  load.imposed.push_back({m->nodesOfCells(master), 1, model::SpaceFunction(0.0)});
  load.imposed.push_back({m->nodesOfCells(m->cellGroup("GAUCHE")), 0, model::SpaceFunction(0.0)});
  if (cornerHeld)
    for (int n : out.slave)
      if (m->node(n).norm() < 1e-12) load.imposed.push_back({{n}, 1, model::SpaceFunction(0.0)});
  const auto top = m->nodesOfCells(m->cellGroup("HAUT"));
  if (loading == Load::Lift) load.imposed.push_back({top, 1, model::SpaceFunction(0.02)});
  if (loading == Load::PushDown) load.imposed.push_back({top, 1, model::SpaceFunction(2 * y0)});
  if (loading == Load::Press)
    load.edgeForces.push_back({m->cellGroup("HAUT"), model::SpaceFunction(0.0), model::SpaceFunction(-c.p)});

  analysis::MechanicalProblem problem;
  problem.model = model;
  problem.materials = materials;
  problem.loads.push_back({&load, nullptr});
  problem.kinematics.assign(model->cells().size(), c.kinematics);
  analysis::MechanicalSystem system(problem);
  analysis::ContactSettings settings;
  settings.continueFormulation = c.continueFormulation;
  zone.penalty = c.penalty;
  analysis::ContactZone z;
  z.masterCells = master;
  z.slaveCells = m->cellGroup("BAS");
  z.settings = zone;
  auto terms = analysis::makeContactTerms(system, {z}, settings);
  analysis::NewtonSettings ns;
  ns.resiGlobRela = 1e-12;
  ns.iterGlobMaxi = 50;
  analysis::StaticNonlinear newton(system, terms.get(), ns);
  analysis::ConvergenceTable table(true);
  if (print) newton.addObserver(table);
  Eigen::VectorXd U = Eigen::VectorXd::Zero(newton.unknownCount());
  if (print) testing::internal::CaptureStdout();
  newton.run(U, {0.0, 1.0}, [&](const analysis::ConvergedInstant& ci) {
    out.iterations = ci.iterations;
    out.depl = mesh::NodalField{"DEPL", {"DX", "DY"}, std::vector<double>(2 * m->nodeCount(), 0.0)};
    for (int n = 0; n < m->nodeCount(); ++n)
      for (int k = 0; k < 2; ++k)
        if (system.dof(n, k) >= 0) out.depl.values[2 * n + k] = (*ci.U)(system.dof(n, k));
    terms->extendDisplacement(*ci.U, out.depl);
    std::vector<mesh::NodalField> fields;
    terms->outputFields(*ci.U, fields);
    EXPECT_EQ(fields.size(), 1u);
    out.cont = fields.at(0);
  });
  if (print) out.table = testing::internal::GetCapturedStdout();
  out.status = terms->statusText();
  return out;
}

// The share of BAS's length of a slave node at X (int N_i dGamma).
double share(const Case& c, double X) {
  const double h = 1.0 / c.N;
  const long i = std::lround(X * 2 * c.N);
  const bool end = i == 0 || i == 2 * c.N;
  if (c.cell == mesh::CellType::QUAD8) return i % 2 ? 2 * h / 3 : (end ? 1 : 2) * h / 6;
  return (end ? 1 : 2) * h / 2;
}

struct Exact {
  double l1 = 1, l2 = 1, s = 0;
};

Exact pressedBlock(const Case& c) {
  Exact e;
  const double p = c.p;
  if (c.kinematics == mechanics::Kinematics::GreenLagrange) {
    EXPECT_EQ(c.modelisation, model::Modelisation::PlaneStrain);
    const double Eb = kE / (1 - kNu * kNu);
    // Eb l2 (l2^2 - 1) / 2 + p = 0 by Newton from l2 = 1.
    double l2 = 1;
    for (int k = 0; k < 50; ++k) l2 -= (Eb * l2 * (l2 * l2 - 1) / 2 + p) / (Eb * (3 * l2 * l2 - 1) / 2);
    const double E22 = (l2 * l2 - 1) / 2, E11 = -kNu / (1 - kNu) * E22;
    e.l2 = l2;
    e.l1 = std::sqrt(1 + 2 * E11);
  } else if (c.modelisation == model::Modelisation::PlaneStrain) {
    e.l2 = 1 - (1 - kNu * kNu) * p / kE;
    e.l1 = 1 + kNu * (1 + kNu) * p / kE;
  } else {
    e.l2 = 1 - p / kE;
    e.l1 = 1 + kNu * p / kE;
  }
  if (c.penalty > 0) e.s = -p / c.penalty;
  return e;
}

class PressedBlock : public ::testing::TestWithParam<Case> {};

TEST_P(PressedBlock, EverySlaveNodeCarriesTheExactPressure) {
  const Case c = GetParam();
  const Outcome o = solve(c, Load::Press);
  const Exact e = pressedBlock(c);
  const double tol = 1e-10;
  ASSERT_EQ(o.cont.name, "CONT_NOEU");
  EXPECT_EQ(o.cont.components, (std::vector<std::string>{"CONT", "JEU", "RN", "RNX", "RNY"}));
  ASSERT_EQ(o.slave.size(), static_cast<std::size_t>(c.cell == mesh::CellType::QUAD8 ? 2 * c.N + 1 : c.N + 1));
  double forces = 0;
  for (int n : o.slave) {
    const double X = o.mesh->node(n)(0);
    SCOPED_TRACE("slave node at X = " + std::to_string(X));
    EXPECT_EQ(at(o.cont, n, "CONT"), 1.0);
    EXPECT_NEAR(at(o.cont, n, "JEU"), e.s, tol);
    EXPECT_NEAR(at(o.cont, n, "RN"), -c.p, tol);
    EXPECT_NEAR(at(o.cont, n, "RNX"), 0.0, tol);
    EXPECT_NEAR(at(o.cont, n, "RNY"), c.p * share(c, X), tol);
    forces += at(o.cont, n, "RNY");
    if (c.continueFormulation) {
      EXPECT_NEAR(at(o.depl, n, "LAGS_C"), -c.p, tol);
    }
  }
  EXPECT_NEAR(forces, c.p * 1.0, tol);  // p times the width
  for (int n = 0; n < o.blockNodes; ++n) {
    const Eigen::Vector3d X = o.mesh->node(n);
    EXPECT_NEAR(at(o.depl, n, "DX"), (e.l1 - 1) * X(0), tol) << "node " << n;
    EXPECT_NEAR(at(o.depl, n, "DY"), (e.l2 - 1) * X(1) + e.s, tol) << "node " << n;
  }
  // Every node in contact, and a contact residual at round-off.
  const int nodes = static_cast<int>(o.slave.size());
  if (c.continueFormulation)
    EXPECT_NE(o.status.find(", " + std::to_string(nodes) + " nodes,"), std::string::npos) << o.status;
  else
    EXPECT_EQ(o.status.rfind(std::to_string(nodes) + " active nodes", 0), 0u) << o.status;
  EXPECT_LE(residualOf(o.status), 1e-12) << o.status;
}

TEST_P(PressedBlock, LiftedBlockLeavesNoContact) {
  const Case c = GetParam();
  const Outcome o = solve(c, Load::Lift);
  for (int n : o.slave) {
    SCOPED_TRACE("slave node " + std::to_string(n));
    EXPECT_EQ(at(o.cont, n, "CONT"), 0.0);
    EXPECT_NEAR(at(o.cont, n, "JEU"), 0.02, 1e-12);
    EXPECT_NEAR(at(o.cont, n, "RN"), 0.0, 1e-12);
    EXPECT_NEAR(at(o.cont, n, "RNX"), 0.0, 1e-12);
    EXPECT_NEAR(at(o.cont, n, "RNY"), 0.0, 1e-12);
    EXPECT_NEAR(at(o.depl, n, "DX"), 0.0, 1e-12);
    EXPECT_NEAR(at(o.depl, n, "DY"), 0.02, 1e-12);
    if (c.continueFormulation) {
      EXPECT_NEAR(at(o.depl, n, "LAGS_C"), 0.0, 1e-12);
    }
  }
  // The active set is empty.
  EXPECT_EQ(o.status.rfind(c.continueFormulation ? "0 points in contact, 0 nodes," : "0 active nodes,", 0), 0u)
      << o.status;
}

Case make(std::string name, mesh::CellType cell, bool cont) {
  Case c;
  c.name = std::move(name) + (cont ? "_CONTINUE" : "_DISCRETE");
  c.cell = cell;
  c.continueFormulation = cont;
  return c;
}

std::vector<Case> cases() {
  std::vector<Case> out;
  for (bool cont : {false, true})
    for (auto cell : {mesh::CellType::QUAD4, mesh::CellType::QUAD8}) {
      const std::string seg = cell == mesh::CellType::QUAD4 ? "SEG2" : "SEG3";
      // Slave nodes on the master's nodes (4 master cells of 0.5, 4 slave cells of 0.25).
      out.push_back(make(seg + "_matching", cell, cont));
      // 3 slave cells on 2 master cells spanning exactly [0, 1]: no node shared.
      Case a = make(seg + "_3_slave_cells_on_2_master_cells", cell, cont);
      a.N = 3, a.masterSegments = 2, a.masterRight = 1.0, a.masterLeft = 0.0;
      out.push_back(a);
      // One long master cell under 4 slave cells.
      Case b = make(seg + "_one_long_master_cell", cell, cont);
      b.masterSegments = 1;
      out.push_back(b);
      // A master overhanging the block, in 3 cells.
      Case d = make(seg + "_3_overhanging_master_cells", cell, cont);
      d.masterSegments = 3;
      out.push_back(d);
      Case e = make(seg + "_C_PLAN", cell, cont);
      e.modelisation = model::Modelisation::PlaneStress;
      out.push_back(e);
      Case f = make(seg + "_GROT_GDEP", cell, cont);
      f.kinematics = mechanics::Kinematics::GreenLagrange;
      f.p = 0.1;  // 10.8 % shortening (9.1 % in small strain)
      out.push_back(f);
      Case g = make(seg + "_PENALISATION", cell, cont);
      g.penalty = 5.0;  // penetration p / 5
      g.masterSegments = 3;
      out.push_back(g);
      Case h = make(seg + "_PENALISATION_GROT_GDEP", cell, cont);
      h.penalty = 20.0;
      h.kinematics = mechanics::Kinematics::GreenLagrange;
      h.p = 0.1;
      h.N = 3, h.masterSegments = 2, h.masterRight = 1.0, h.masterLeft = 0.0;
      out.push_back(h);
    }
  return out;
}

INSTANTIATE_TEST_SUITE_P(Contact, PressedBlock, ::testing::ValuesIn(cases()),
                         [](const auto& info) { return info.param.name; });

TEST(ContactPatchExact, LargeStrainSolutionDiffersFromTheLinearOne) {
  // The GROT_GDEP cases test something the small-strain ones do not.
  Case c;
  c.kinematics = mechanics::Kinematics::GreenLagrange;
  c.p = 0.1;
  const Exact e = pressedBlock(c);
  EXPECT_NEAR(e.l2, 0.8922, 1e-4);  // l2 (l2^2 - 1) / 2 = -0.091
  EXPECT_GT(std::fabs((e.l2 - 1) - (-(1 - kNu * kNu) * c.p)), 0.015);
}

// DIST_APPA: a block pushed 0.2 down onto a master 0.1 below its bottom.
TEST(ContactPatchExact, PairingDistanceLimitsThePairing) {
  for (bool cont : {false, true})
    for (auto cell : {mesh::CellType::QUAD4, mesh::CellType::QUAD8}) {
      SCOPED_TRACE(std::string(cont ? "CONTINUE " : "DISCRETE ") + (cell == mesh::CellType::QUAD4 ? "SEG2" : "SEG3"));
      Case c = make("push", cell, cont);
      // Paired: bottom stopped at -0.1, eps_yy = -0.1, sigma_yy = E / (1 - NU^2) eps_yy.
      const Outcome paired = solve(c, Load::PushDown, {}, -0.1);
      const double sigma = -0.1 * kE / (1 - kNu * kNu);
      for (int n : paired.slave) {
        EXPECT_EQ(at(paired.cont, n, "CONT"), 1.0);
        EXPECT_NEAR(at(paired.cont, n, "JEU"), 0.0, 1e-10);
        EXPECT_NEAR(at(paired.cont, n, "RN"), sigma, 1e-10);
        EXPECT_NEAR(at(paired.depl, n, "DY"), -0.1, 1e-10);
        EXPECT_NEAR(at(paired.depl, n, "DX"), kNu / (1 - kNu) * 0.1 * paired.mesh->node(n)(0), 1e-10);
      }
      // DIST_APPA = 0.05 < 0.1: never paired, the block translates by -0.2 through the master.
      analysis::ZoneSettings z;
      z.maxDistance = 0.05;
      const Outcome free = solve(c, Load::PushDown, z, -0.1);
      for (int n : free.slave) {
        EXPECT_EQ(at(free.cont, n, "CONT"), 0.0);
        EXPECT_EQ(at(free.cont, n, "JEU"), 0.0);  // unpaired
        EXPECT_NEAR(at(free.cont, n, "RN"), 0.0, 1e-12);
        EXPECT_NEAR(at(free.depl, n, "DY"), -0.2, 1e-12);
        EXPECT_NEAR(at(free.depl, n, "DX"), 0.0, 1e-12);
      }
    }
}

// SANS_GROUP_NO: the corner (0, 0), also held by DY = 0, is excluded from contact.
TEST(ContactPatchExact, ExcludedNodeCarriesNoContact) {
  for (bool cont : {false, true})
    for (auto cell : {mesh::CellType::QUAD4, mesh::CellType::QUAD8}) {
      SCOPED_TRACE(std::string(cont ? "CONTINUE " : "DISCRETE ") + (cell == mesh::CellType::QUAD4 ? "SEG2" : "SEG3"));
      Case c = make("excluded", cell, cont);
      auto m = test_support::squareMesh(c.N, c.cell);
      int corner = -1;
      for (int n : m.nodesOfCells(m.cellGroup("BAS")))
        if (m.node(n).norm() < 1e-12) corner = n;
      ASSERT_GE(corner, 0);
      analysis::ZoneSettings z;
      z.excludedNodes = {corner};
      const Outcome o = solve(c, Load::Press, z, 0.0, true);
      EXPECT_EQ(at(o.cont, corner, "CONT"), 0.0);
      EXPECT_NEAR(at(o.cont, corner, "RN"), 0.0, 1e-14);
      EXPECT_NEAR(at(o.cont, corner, "JEU"), 0.0, 1e-12);  // held by DY = 0
      if (cont) {
        EXPECT_NEAR(at(o.depl, corner, "LAGS_C"), 0.0, 1e-14);
        continue;  // LAGS_C = 0 at the corner: the pressure is not uniform near it
      }
      // DISCRETE: the support takes the corner's share; the rest is exact.
      EXPECT_NEAR(at(o.cont, corner, "RNX"), 0.0, 1e-14);
      EXPECT_NEAR(at(o.cont, corner, "RNY"), 0.0, 1e-14);
      for (int n : o.slave) {
        if (n == corner) continue;
        EXPECT_EQ(at(o.cont, n, "CONT"), 1.0);
        EXPECT_NEAR(at(o.cont, n, "RN"), -c.p, 1e-10);
        EXPECT_NEAR(at(o.cont, n, "JEU"), 0.0, 1e-10);
      }
    }
}

// CONTACT_INIT: the statuses of the first Newton iteration. The block hangs
// 0.01 above the master and is pushed 0.02 down: the same exact solution
// whatever the initial statuses, eps_yy = -0.01.
TEST(ContactPatchExact, ContactInitSetsTheFirstIterationStatuses) {
  const int points = 4 * 3;  // 4 slave cells, 3 Gauss points each
  for (auto [init, first] : std::vector<std::pair<contact::ForcedStatus, int>>{
           {contact::ForcedStatus::None, 0}, {contact::ForcedStatus::Contact, points}, {contact::ForcedStatus::Separated, 0}}) {
    Case c = make("init", mesh::CellType::QUAD4, true);
    analysis::ZoneSettings z;
    z.initialStatus = init;
    const Outcome o = solve(c, Load::PushDown, z, -0.01, false, true);
    std::smatch m;
    ASSERT_TRUE(std::regex_search(o.table, m, std::regex("\n +0  [^\n]* (\\d+) points in contact"))) << o.table;
    EXPECT_EQ(std::stoi(m[1]), first) << o.table;
    for (int n : o.slave) {
      EXPECT_NEAR(at(o.depl, n, "DY"), -0.01, 1e-10);
      EXPECT_NEAR(at(o.depl, n, "LAGS_C"), -0.01 * kE / (1 - kNu * kNu), 1e-10);
    }
  }
  // A block touching the master is in contact at the first iteration, unless CONTACT_INIT='NON'.
  for (auto [init, first] : std::vector<std::pair<contact::ForcedStatus, int>>{{contact::ForcedStatus::None, points},
                                                                               {contact::ForcedStatus::Separated, 0}}) {
    Case c = make("init", mesh::CellType::QUAD4, true);
    analysis::ZoneSettings z;
    z.initialStatus = init;
    const Outcome o = solve(c, Load::Lift, z, 0.0, false, true);
    std::smatch m;
    ASSERT_TRUE(std::regex_search(o.table, m, std::regex("\n +0  [^\n]* (\\d+) points in contact"))) << o.table;
    EXPECT_EQ(std::stoi(m[1]), first) << o.table;
  }
}

// COEF_CONT is used as given (a pressure per unit gap, as code_aster's), not scaled
// by Young's modulus. One QUAD4 block [0, 1]^2 with E = 1E9 held 0.1 above a master
// SEG2, LAGS_C = -5 at both slave nodes: the points are separated (-5 + 100 x 0.1 > 0),
// so the LAGS_C equation of node v is -int L_v LAGS_C / COEF_CONT = 5 x 0.5 / 100 = 0.025,
// assembled times the zone's scale S = E (contact_terms.hpp), and the status residual
// (that equation over int L_v = 0.5, in length units) is |LAGS_C| / COEF_CONT = 0.05.
// Relative to E it would be 1E9 times smaller.
TEST(ContactCoefCont, IsAPressurePerUnitGapUsedAsGiven) {
  constexpr double E = 1e9, rho = 100.0, lagsC = -5.0;
  auto m = std::make_shared<mesh::Mesh>(test_support::squareMesh(1, mesh::CellType::QUAD4));
  const int a = m->addNode(Eigen::Vector3d(1.5, -0.1, 0)), b = m->addNode(Eigen::Vector3d(-0.5, -0.1, 0));
  m->addCellGroup("MAITRE", {m->addCell(mesh::CellType::SEG2, {a, b})});
  auto model = std::make_shared<model::Model>(m);
  std::vector<int> all(m->cellCount());
  for (int i = 0; i < m->cellCount(); ++i) all[i] = i;
  model->assign(all, model::Modelisation::PlaneStrain);
  auto material = std::make_shared<model::ElasticMaterial>();
  material->E = E;
  material->NU = kNu;
  auto materials = std::make_shared<model::MaterialField>(m->cellCount());
  materials->assign(all, material);
  analysis::MechanicalProblem problem;
  problem.model = model;
  problem.materials = materials;
  problem.kinematics.assign(model->cells().size(), mechanics::Kinematics::SmallStrain);
  analysis::MechanicalSystem system(problem);
  analysis::ContactSettings settings;
  settings.continueFormulation = true;
  analysis::ContactZone z;
  z.masterCells = m->cellGroup("MAITRE");
  z.slaveCells = m->cellGroup("BAS");
  z.settings.rho = rho;
  auto terms = analysis::makeContactTerms(system, {z}, settings);
  const int first = system.dofCount();
  terms->setFirstUnknown(first);
  const int n = first + terms->unknownCount();
  ASSERT_EQ(terms->unknownCount(), 2);
  Eigen::VectorXd U = Eigen::VectorXd::Zero(n);
  for (int k = 0; k < 2; ++k) U(first + k) = lagsC / E;  // the unknowns are LAGS_C / S
  terms->update(U);
  fem::ElementDofs dofs = system.elementDofs();
  const int firstElement = dofs.elementCount();
  terms->elementDofs(dofs);
  for (int i = 0; i < n; ++i) dofs.add(&i, 1);
  fem::AssemblyPattern pattern(n, dofs);
  linalg::SparseMatrix K;
  pattern.takeMatrix(K);
  Eigen::VectorXd r = Eigen::VectorXd::Zero(n);
  terms->assemble(U, r, pattern, firstElement, &K);
  for (int k = 0; k < 2; ++k) EXPECT_NEAR(r(first + k), E * (-lagsC * 0.5 / rho), 1e-9 * E * 0.025);
  EXPECT_NEAR(residualOf(terms->statusText()), -lagsC / rho, 1e-6) << terms->statusText();
  EXPECT_EQ(terms->statusText().rfind("0 points in contact", 0), 0u) << terms->statusText();
}

}  // namespace
