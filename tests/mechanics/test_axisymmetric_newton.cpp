// AXIS in GROT_GDEP through MechanicalSystem and the Newton driver: a thick tube
// r in [1, 2] (and a solid cylinder r in [0, 1], nodes on the axis) in plane
// strain along the axis (DY = 0 on both ends), loaded by a large follower pressure
// (TYPE_CHARGE='SUIV', its tangent in the Newton matrix). With the exact tangent
// (hoop geometric term and the pressure's dr/du included) the residuals converge
// quadratically: once below 1e-3, each residual is below 10 x the square of the one
// before (or at rounding, 1e-13).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "../support/square_mesh.hpp"
#include "analysis/mechanical_system.hpp"
#include "analysis/static_nonlinear.hpp"
#include "expr/expression.hpp"
#include "mesh/orient.hpp"

using namespace aster;

namespace {

struct Outcome {
  std::vector<std::vector<double>> residuals;  // per instant
  Eigen::VectorXd U;
  std::shared_ptr<mesh::Mesh> mesh;
  std::unique_ptr<analysis::MechanicalSystem> system;
};

// The unit square moved to r in [r0, r0 + 1]; pressure p t on the face `loaded`, t = 0.5, 1.
void solveTube(double r0, const std::string& loaded, double p, mesh::CellType type, Outcome& o) {
  o.mesh = std::make_shared<mesh::Mesh>(test_support::squareMesh(4, type));
  for (int n = 0; n < o.mesh->nodeCount(); ++n) o.mesh->setNode(n, o.mesh->node(n) + Eigen::Vector3d(r0, 0, 0));
  mesh::orientBoundarySegments(*o.mesh, o.mesh->cellGroup(loaded));  // the pressure pushes (ORIE_PEAU)
  auto model = std::make_shared<model::Model>(o.mesh);
  std::vector<int> all(o.mesh->cellCount());
  for (int c = 0; c < o.mesh->cellCount(); ++c) all[c] = c;
  model->assign(all, model::Modelisation::Axisymmetric);
  ASSERT_TRUE(model->axisymmetric());
  auto materials = std::make_shared<model::MaterialField>(o.mesh->cellCount());
  auto steel = std::make_shared<model::ElasticMaterial>();
  steel->E = 100.0;
  steel->NU = 0.3;
  materials->assign(o.mesh->cellGroup("SURFACE"), steel);
  static model::MechanicalLoad support, pressure;
  support = {};
  pressure = {};
  support.imposed.push_back({o.mesh->nodesOfCells(o.mesh->cellGroup("BAS")), 1, model::SpaceFunction(0.0)});
  support.imposed.push_back({o.mesh->nodesOfCells(o.mesh->cellGroup("HAUT")), 1, model::SpaceFunction(0.0)});
  pressure.pressures.push_back({o.mesh->cellGroup(loaded), model::SpaceFunction(p)});
  analysis::MechanicalProblem problem;
  problem.model = model;
  problem.materials = materials;
  problem.loads.push_back({&support, nullptr});
  analysis::AppliedLoad follower{&pressure, expr::Expression::compile("INST", {"INST"})};  // p t
  follower.follower = true;
  problem.loads.push_back(follower);
  problem.kinematics.assign(model->cells().size(), mechanics::Kinematics::GreenLagrange);
  o.system = std::make_unique<analysis::MechanicalSystem>(problem);
  analysis::NewtonSettings settings;
  settings.resiGlobRela = 1e-12;
  settings.iterGlobMaxi = 20;
  analysis::StaticNonlinear newton(*o.system, nullptr, settings);
  o.U = Eigen::VectorXd::Zero(newton.unknownCount());
  newton.run(o.U, {0.0, 0.5, 1.0},
             [&](const analysis::ConvergedInstant& c) { o.residuals.push_back(c.residuals); });
}

void expectQuadratic(const Outcome& o) {
  ASSERT_EQ(o.residuals.size(), 2u);
  for (const auto& r : o.residuals) {
    std::string trace;
    char buf[32];
    for (double v : r) trace += (std::snprintf(buf, sizeof buf, " %.3g", v), buf);
    SCOPED_TRACE("residuals" + trace);
    std::printf("RESI_GLOB_RELA per iteration:%s\n", trace.c_str());
    EXPECT_LE(r.size(), 8u);
    int quadraticSteps = 0;
    for (std::size_t k = 0; k + 1 < r.size(); ++k) {
      if (r[k] > 1e-3 || r[k + 1] < 1e-13) continue;
      EXPECT_LT(r[k + 1], 10 * r[k] * r[k]) << "iteration " << k + 1;
      ++quadraticSteps;
    }
    EXPECT_GE(quadraticSteps, 1);
  }
}

TEST(AxisymmetricNewton, ThickTubeUnderFollowerPressureConvergesQuadratically) {
  for (auto type : {mesh::CellType::QUAD8, mesh::CellType::TRIA6, mesh::CellType::QUAD4}) {
    SCOPED_TRACE(mesh::cellTypeName(type));
    Outcome o;
    solveTube(1.0, "GAUCHE", 6.0, type, o);  // inner face r = 1
    expectQuadratic(o);
    // A large strain: the inner radius grows by more than 10 %.
    const int corner = 0;  // (1, 0)
    EXPECT_GT(o.U(o.system->dof(corner, 0)), 0.1);
  }
}

TEST(AxisymmetricNewton, SolidCylinderTouchingTheAxis) {
  Outcome o;
  solveTube(0.0, "DROITE", 10.0, mesh::CellType::QUAD8, o);  // outer face r = 1, compressed
  expectQuadratic(o);
  // The homogeneous state u_r = (l - 1) r, u_z = 0 is exact: F = diag(l, 1, l) (r, z, t),
  // E_rr = E_tt = e = (l^2 - 1)/2, S_rr = S_tt = 2 (lambda + mu) e; per radian on r = 1
  // the first Piola force l S_rr balances the follower pressure on the current face,
  // -p l: S_rr = -p, so e = -p / (2 (lambda + mu)) and l = sqrt(1 + 2 e).
  const double lambda = 100.0 * 0.3 / (1.3 * 0.4), mu = 100.0 / 2.6;
  const double l = std::sqrt(1 - 2 * 10.0 / (2 * (lambda + mu)));
  int axisNodes = 0;
  for (int n = 0; n < o.mesh->nodeCount(); ++n) {
    const int d = o.system->dof(n, 0);
    if (d < 0) continue;  // a grid node no cell uses
    EXPECT_NEAR(o.U(d), (l - 1) * o.mesh->node(n)(0), 1e-10);
    axisNodes += o.mesh->node(n)(0) == 0.0;
  }
  EXPECT_EQ(axisNodes, 9);  // 4 QUAD8 along the axis: 9 nodes at r = 0, whose u_r is 0
}

}  // namespace
