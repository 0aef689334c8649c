// One QUAD4 of the unit square in plane strain, Saint Venant-Kirchhoff (GROT_GDEP) with
// NU = 0: under a dead traction P on DROITE (DX = 0 on GAUCHE, DY = 0 on BAS) the stretch
// l is uniform, the lateral one stays 1, and P = E l (l^2 - 1) / 2 (E = 1). From the
// tangent at rest (E), the first Newton step u = P / E overshoots the root far: the
// response stiffens. For the tests of the Newton driver's line search and step cutting.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "../support/square_mesh.hpp"
#include "analysis/static_nonlinear.hpp"
#include "core/error.hpp"
#include "expr/expression.hpp"

namespace aster::test_support {

// The bar's mesh, its plane strain model and its material (E = 1, NU = 0); loads are the caller's.
struct Bar {
  std::shared_ptr<mesh::Mesh> mesh;
  std::shared_ptr<model::Model> model;
  std::shared_ptr<model::MaterialField> materials;
};

inline Bar unitBar() {
  Bar bar;
  bar.mesh = std::make_shared<mesh::Mesh>(squareMesh(1, mesh::CellType::QUAD4));
  bar.model = std::make_shared<model::Model>(bar.mesh);
  std::vector<int> all(bar.mesh->cellCount());
  for (int c = 0; c < bar.mesh->cellCount(); ++c) all[c] = c;
  bar.model->assign(all, model::Modelisation::PlaneStrain);
  auto material = std::make_shared<model::ElasticMaterial>();
  material->E = 1.0;
  material->NU = 0.0;
  bar.materials = std::make_shared<model::MaterialField>(bar.mesh->cellCount());
  bar.materials->assign(all, material);
  return bar;
}

struct BarRun {
  double u = 0;  // DX of DROITE at the last instant
  int iterations = 0;  // of the last instant
  bool converged = true;
  std::string error;  // why it did not
  analysis::NewtonStatistics statistics;
};

// ramp: the traction is P t over the instants 0, 1 (else P at every instant).
inline BarRun pullBar(double P, const analysis::NewtonSettings& settings, bool ramp = false,
                      analysis::NewtonObserver* observer = nullptr) {
  const Bar bar = unitBar();
  const auto& m = bar.mesh;
  model::MechanicalLoad load;
  load.imposed.push_back({m->nodesOfCells(m->cellGroup("GAUCHE")), 0, model::SpaceFunction(0.0)});
  load.imposed.push_back({m->nodesOfCells(m->cellGroup("BAS")), 1, model::SpaceFunction(0.0)});
  load.edgeForces.push_back({m->cellGroup("DROITE"), model::SpaceFunction(P), model::SpaceFunction(0.0)});
  analysis::MechanicalProblem problem;
  problem.model = bar.model;
  problem.materials = bar.materials;
  problem.loads.push_back({&load, ramp ? expr::Expression::compile("INST", {"INST"}) : nullptr});
  problem.kinematics.assign(bar.model->cells().size(), mechanics::Kinematics::GreenLagrange);
  analysis::MechanicalSystem system(problem);
  analysis::StaticNonlinear newton(system, nullptr, settings);
  if (observer) newton.addObserver(*observer);
  Eigen::VectorXd U = Eigen::VectorXd::Zero(newton.unknownCount());
  BarRun out;
  try {
    newton.run(U, {0.0, 1.0}, [&](const analysis::ConvergedInstant& c) { out.iterations = c.iterations; });
  } catch (const Error& e) {
    out.converged = false;
    out.error = e.what();
  }
  out.statistics = newton.statistics();
  if (!out.converged) return out;
  const int corner = m->nodesOfCells(m->cellGroup("DROITE")).front();
  out.u = U(system.dof(corner, 0));
  return out;
}

// The root of l (l^2 - 1) / 2 = P by Newton on the scalar equation (independent of the FE code).
inline double stretchOf(double P) {
  double l = 2;
  for (int i = 0; i < 100; ++i) l -= (l * (l * l - 1) / 2 - P) / ((3 * l * l - 1) / 2);
  return l;
}

}  // namespace aster::test_support
