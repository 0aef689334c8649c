// The Newton driver on SSNP150's manufactured solution without contact
// (Dirichlet on HAUT and BAS, tractions on GAUCHE and DROITE, body force):
// quadratic convergence of Newton, and the L2 error rates of each cell type.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include <Eigen/LU>

#include "../support/square_mesh.hpp"
#include "expr/expression.hpp"
#include "mechanics/manufactured.hpp"
#include "fem/mesh_cell_type.hpp"
#include "fem/cell_type.hpp"
#include "fem/quadrature.hpp"
#include "fem/shape_functions.hpp"
#include "analysis/convergence_table.hpp"
#include "analysis/static_nonlinear.hpp"
#include "core/error.hpp"

using namespace aster;

namespace {

const char* kUx = "-0.2*Y**3*(X-0.5)";
const char* kUy = "-0.05*(X-0.5)**2*(1+Y) - 0.01*Y";


struct Outcome {
  double l2Error = 0;
  std::vector<std::vector<double>> residuals;  // per instant
  analysis::NewtonStatistics statistics;
};

// observer: told of the run; iterGlobMaxi: ITER_GLOB_MAXI.
Outcome solve(int N, mesh::CellType type, mechanics::Kinematics kin, int steps,
              analysis::NewtonObserver* observer = nullptr, int iterGlobMaxi = 20) {
  auto m = std::make_shared<mesh::Mesh>(test_support::squareMesh(N, type));
  auto model = std::make_shared<model::Model>(m);
  std::vector<int> all(m->cellCount());
  for (int c = 0; c < m->cellCount(); ++c) all[c] = c;
  model->assign(all, model::Modelisation::PlaneStrain);
  auto material = std::make_shared<model::ElasticMaterial>();
  material->E = 1.0;
  material->NU = 0.3;
  auto materials = std::make_shared<model::MaterialField>(m->cellCount());
  materials->assign(all, material);

  const auto ux = expr::Expression::compile(kUx, {"X", "Y"});
  const auto uy = expr::Expression::compile(kUy, {"X", "Y"});
  auto sol = std::make_shared<mechanics::ManufacturedElasticity>(
      ux, uy, 1.0, 0.3, mechanics::PlaneHypothesis::PlaneStrain, kin);
  using Q = mechanics::ManufacturedQuantity;
  auto F = [&](Q q, int c, Eigen::Vector2d n = Eigen::Vector2d::Zero()) {
    return model::SpaceFunction(mechanics::manufacturedFunction(sol, q, c, n));
  };
  model::MechanicalLoad load;
  for (const char* g : {"HAUT", "BAS"})
    for (int c = 0; c < 2; ++c)
      load.imposed.push_back({m->nodesOfCells(m->cellGroup(g)), c, model::SpaceFunction(c == 0 ? ux : uy)});
  load.edgeForces.push_back({m->cellGroup("DROITE"), F(Q::Traction, 0, {1, 0}), F(Q::Traction, 1, {1, 0})});
  load.edgeForces.push_back({m->cellGroup("GAUCHE"), F(Q::Traction, 0, {-1, 0}), F(Q::Traction, 1, {-1, 0})});
  load.bodyForces.push_back({m->cellGroup("SURFACE"), F(Q::BodyForce, 0), F(Q::BodyForce, 1)});
  auto ramp = expr::Expression::compile("INST", {"INST"});

  analysis::MechanicalProblem problem;
  problem.model = model;
  problem.materials = materials;
  problem.loads.push_back({&load, ramp});
  problem.kinematics.assign(model->cells().size(), kin);
  analysis::MechanicalSystem system(problem);
  analysis::NewtonSettings settings;
  settings.resiGlobRela = 1e-10;
  settings.iterGlobMaxi = iterGlobMaxi;
  analysis::StaticNonlinear newton(system, nullptr, settings);
  if (observer) newton.addObserver(*observer);
  Eigen::VectorXd U = Eigen::VectorXd::Zero(newton.unknownCount());
  std::vector<double> times;
  for (int k = 0; k <= steps; ++k) times.push_back(double(k) / steps);
  Outcome out;
  newton.run(U, times, [&](const analysis::ConvergedInstant& c) { out.residuals.push_back(c.residuals); });
  out.statistics = newton.statistics();

  // L2 error of the displacement, 6x6 Gauss points per quadrangle, degree 10 on triangles.
  double e2 = 0;
  for (int c : m->cellGroup("SURFACE")) {
    const auto nodes = m->cellNodes(c);
    fem::dispatchSurface(fem::referenceCell(m->cellType(c), "test"), [&](auto tag) {
      constexpr fem::CellType T = decltype(tag)::value;
      using C = fem::Cell<T>;
      const auto& rule = (T == fem::CellType::TRIA3 || T == fem::CellType::TRIA6) ? fem::gaussTriangle(6)
                                                                                   : fem::gaussQuadrangle(6);
      for (int q = 0; q < rule.size(); ++q) {
        const auto N = C::values(rule.points[q]);
        const auto dN = C::gradients(rule.points[q]);
        Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
        double X = 0, Y = 0, uh[2] = {0, 0};
        for (int a = 0; a < C::nodes; ++a) {
          const Eigen::Vector3d p = m->node(nodes[a]);
          X += N(a) * p(0);
          Y += N(a) * p(1);
          J += p.head<2>() * dN.row(a);
          for (int k = 0; k < 2; ++k) uh[k] += N(a) * U(system.dof(nodes[a], k));
        }
        const double args[2] = {X, Y};
        const double d0 = uh[0] - ux->evaluate(args), d1 = uh[1] - uy->evaluate(args);
        e2 += rule.weights[q] * J.determinant() * (d0 * d0 + d1 * d1);
      }
    });
  }
  out.l2Error = std::sqrt(e2);
  return out;
}

}  // namespace

TEST(StaticNonlinear, NewtonConvergesQuadraticallyOnSsnp150WithoutContact) {
  const Outcome o = solve(8, mesh::CellType::QUAD8, mechanics::Kinematics::GreenLagrange, 4);
  ASSERT_EQ(o.residuals.size(), 4u);
  for (const auto& r : o.residuals) {
    ASSERT_GE(r.size(), 3u);
    EXPECT_LE(r.back(), 1e-10);
    // Quadratic: once below 1e-2, each residual is at most ~ the square of the
    // previous, until round-off (1e-13) is reached.
    int checked = 0;
    for (std::size_t k = 1; k + 1 < r.size(); ++k)
      if (r[k] < 1e-2 && r[k + 1] > 1e-13) {
        EXPECT_LE(r[k + 1], 10 * r[k] * r[k]) << "iteration " << k;
        ++checked;
      }
    EXPECT_GE(checked, 1);
  }
}

// Near convergence the residual is assembled alone first: every tangent assembled is
// factorized, none is assembled at an iteration that converges.
TEST(StaticNonlinear, NoTangentIsAssembledForTheConvergedIterate) {
  const Outcome o = solve(8, mesh::CellType::QUAD8, mechanics::Kinematics::GreenLagrange, 4);
  EXPECT_EQ(o.statistics.tangentAssemblies, o.statistics.factorizations);
  EXPECT_EQ(o.statistics.factorizations, o.statistics.iterations);
}

TEST(StaticNonlinear, SmallStrainIsLinearOneIteration) {
  const Outcome o = solve(4, mesh::CellType::QUAD8, mechanics::Kinematics::SmallStrain, 1);
  ASSERT_EQ(o.residuals.size(), 1u);
  EXPECT_EQ(o.residuals[0].size(), 2u);  // prediction, then converged
}

// Records what the driver tells its observers.
struct Recorder : analysis::NewtonObserver {
  struct Step {
    double t0, t1;
    std::vector<analysis::NewtonIteration> iterations;
    int converged = -1;  // iterations told by stepConverged, -1 if not told
  };
  std::vector<Step> steps;
  struct Cut {
    double t0, t1;
    int parts, level;
    std::string why;
  };
  std::vector<Cut> cuts;
  void stepStarted(double t0, double t1) override { steps.push_back({t0, t1, {}, -1}); }
  void iterationDone(const analysis::NewtonIteration& it) override { steps.back().iterations.push_back(it); }
  void stepConverged(double t1, int iterations, bool criteriaMet) override {
    EXPECT_EQ(t1, steps.back().t1);
    EXPECT_TRUE(criteriaMet);
    steps.back().converged = iterations;
  }
  void stepCut(double t0, double t1, int parts, int level, const std::string& why) override {
    cuts.push_back({t0, t1, parts, level, why});
  }
};

// The observer sees each step start, one row per iteration with the residual the driver
// measured (the ConvergedInstant's), the tangent factorized at every iteration but the
// converged one (REAC_ITER = 1, and the converged iterate factorizes nothing), and the
// step converge after as many corrections as the instant reports.
TEST(StaticNonlinear, ObserversAreToldEveryStepAndIteration) {
  Recorder r;
  const Outcome o = solve(4, mesh::CellType::QUAD8, mechanics::Kinematics::GreenLagrange, 2, &r);
  ASSERT_EQ(r.steps.size(), 2u);
  EXPECT_TRUE(r.cuts.empty());
  for (std::size_t s = 0; s < 2; ++s) {
    const auto& step = r.steps[s];
    EXPECT_DOUBLE_EQ(step.t0, 0.5 * s);
    EXPECT_DOUBLE_EQ(step.t1, 0.5 * (s + 1));
    ASSERT_EQ(step.iterations.size(), o.residuals[s].size());
    EXPECT_EQ(step.converged, static_cast<int>(o.residuals[s].size()) - 1);
    for (std::size_t k = 0; k < step.iterations.size(); ++k) {
      const auto& it = step.iterations[k];
      EXPECT_EQ(it.index, static_cast<int>(k));
      EXPECT_EQ(it.time, step.t1);
      EXPECT_EQ(it.rela, o.residuals[s][k]);  // RESI_GLOB_RELA is the criterion
      EXPECT_GE(it.maxi, 0.0);
      EXPECT_GE(it.seconds, 0.0);
      EXPECT_EQ(it.contact, "");
      EXPECT_STREQ(it.matrix, k + 1 < step.iterations.size() ? "TANGENTE" : "");
    }
  }
}

// ITER_GLOB_MAXI = 1 cannot converge the nonlinear step (its first correction only brings
// in the imposed displacements): the failure is told as a cut into SUBD_PAS = 4 sub-steps
// at level 1, and the first sub-step starts.
TEST(StaticNonlinear, ObserversAreToldOfStepCuts) {
  Recorder r;
  try {
    solve(4, mesh::CellType::QUAD8, mechanics::Kinematics::GreenLagrange, 1, &r, 1);
  } catch (const Error&) {
    // Sub-steps may fail too: the cuts told before are what is checked.
  }
  ASSERT_GE(r.cuts.size(), 1u);
  EXPECT_EQ(r.cuts[0].t0, 0.0);
  EXPECT_EQ(r.cuts[0].t1, 1.0);
  EXPECT_EQ(r.cuts[0].parts, 4);
  EXPECT_EQ(r.cuts[0].level, 1);
  EXPECT_NE(r.cuts[0].why.find("ITER_GLOB_MAXI = 1"), std::string::npos) << r.cuts[0].why;
  // Each first sub-step fails too and is cut in turn, down to SUBD_NIVEAU = 3.
  ASSERT_EQ(r.cuts.size(), 3u);
  for (int level = 2; level <= 3; ++level) {
    const auto& cut = r.cuts[level - 1];
    EXPECT_EQ(cut.level, level);
    EXPECT_EQ(cut.t0, 0.0);
    EXPECT_DOUBLE_EQ(cut.t1, std::pow(0.25, level - 1));
  }
  ASSERT_GE(r.steps.size(), 2u);
  EXPECT_EQ(r.steps[0].converged, -1);  // the whole step failed
  EXPECT_DOUBLE_EQ(r.steps[1].t0, 0.0);
  EXPECT_DOUBLE_EQ(r.steps[1].t1, 0.25);
}

// The table's header and rows, column by column (the layout STAT_NON_LINE's output has).
TEST(ConvergenceTable, PrintsAHeaderPerStepAndARowPerIteration) {
  analysis::ConvergenceTable table(true);
  analysis::NewtonIteration it;
  it.time = 0.5;
  it.index = 3;
  it.rela = 1.5e-3;
  it.maxi = 2.25e-7;
  it.matrix = "TANGENTE";
  it.seconds = 0.0123;
  it.contact = "9 active nodes";
  testing::internal::CaptureStdout();
  table.stepStarted(0.25, 0.5);
  table.iterationDone(it);
  it.index = 4;
  it.matrix = "";
  table.iterationDone(it);
  EXPECT_EQ(testing::internal::GetCapturedStdout(),
            "  Instant 5.000000E-01\n"
            "    iter  RESI_GLOB_RELA   RESI_GLOB_MAXI   matrix      time (s)   contact\n"
            "       3  1.500000E-03     2.25E-07         TANGENTE    1.23E-02   9 active nodes\n"
            "       4  1.500000E-03     2.25E-07                     1.23E-02   9 active nodes\n");
}

TEST(ConvergenceTable, WithoutContactTheHeaderEndsAfterTheTime) {
  analysis::ConvergenceTable table(false);
  testing::internal::CaptureStdout();
  table.stepStarted(0.0, 1.0);
  EXPECT_EQ(testing::internal::GetCapturedStdout(),
            "  Instant 1.000000E+00\n    iter  RESI_GLOB_RELA   RESI_GLOB_MAXI   matrix      time (s)   \n");
}

struct RateCase {
  mesh::CellType type;
  double minimumRate;
};

class ErrorRates : public ::testing::TestWithParam<RateCase> {};

TEST_P(ErrorRates, L2ErrorDecreasesAtTheOptimalRate) {
  const RateCase rc = GetParam();
  std::vector<double> e;
  for (int N : {4, 8, 16, 32}) e.push_back(solve(N, rc.type, mechanics::Kinematics::GreenLagrange, 2).l2Error);
  // The rate on N = 4, 8, 16, 32: the least-squares slope of log e against log h.
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < e.size(); ++k) {
    const double x = -std::log(4.0 * std::pow(2.0, static_cast<double>(k))), y = std::log(e[k]);
    sx += x; sy += y; sxx += x * x; sxy += x * y;
  }
  const double n = static_cast<double>(e.size());
  const double fitted = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  EXPECT_GE(fitted, rc.minimumRate) << "errors " << e[0] << ", " << e[1] << ", " << e[2] << ", " << e[3];
  // And between successive meshes: linear cells are still pre-asymptotic on the
  // coarsest pair (TRIA3: 1.87 from N = 4 to 8), which only has to show the order
  // within 0.1; the finer pairs must reach the rate.
  for (std::size_t k = 1; k < e.size(); ++k) {
    const double rate = std::log(e[k - 1] / e[k]) / std::log(2.0);
    const double expected = k == 1 ? rc.minimumRate - 0.1 : rc.minimumRate;
    EXPECT_GE(rate, expected) << "meshes " << k - 1 << " -> " << k << ": " << e[k - 1] << " -> " << e[k];
  }
}

INSTANTIATE_TEST_SUITE_P(Ssnp150WithoutContact, ErrorRates,
                         ::testing::Values(RateCase{mesh::CellType::QUAD8, 2.9}, RateCase{mesh::CellType::QUAD9, 2.9},
                                           RateCase{mesh::CellType::TRIA6, 2.9}, RateCase{mesh::CellType::QUAD4, 1.9},
                                           RateCase{mesh::CellType::TRIA3, 1.9}),
                         [](const auto& info) { return mesh::cellTypeName(info.param.type); });
