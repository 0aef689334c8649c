// The SVK square benchmark: a regular N x N QUAD8 mesh of the unit square,
// plane strain, E = 1, NU = 0.3, Saint Venant-Kirchhoff (GROT_GDEP), bottom
// clamped, top displaced by (0.02, -0.015) in 5 equal increments, Newton to
// RESI_GLOB_RELA = 1e-8. Prints DOFs, Newton iterations, seconds (total,
// assembly, linear solver), peak memory and the final reaction on the top edge
// (force of the support on the body), to compare with other programs.
//   bench_svk_square [N ...] [--solver UMFPACK|CHOLMOD|KLU|EIGEN_LU]
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "support/square_mesh.hpp"
#include "expr/expression.hpp"
#include "solver/static_nonlinear.hpp"

using namespace aster;

namespace {

double peakMegabytes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;
}

void run(int N, const std::string& method) {
  const auto start = std::chrono::steady_clock::now();
  auto m = std::make_shared<mesh::Mesh>(test_support::squareMesh(N, mesh::CellType::QUAD8));
  auto model = std::make_shared<model::Model>(m);
  model->assign(m->cellGroup("SURFACE"), model::Modelisation::PlaneStrain);
  auto material = std::make_shared<model::ElasticMaterial>();
  material->E = 1.0;
  material->NU = 0.3;
  auto materials = std::make_shared<model::MaterialField>(m->cellCount());
  materials->assign(m->cellGroup("SURFACE"), material);
  model::MechanicalLoad load;
  load.kinematic = true;
  const auto bottom = m->nodesOfCells(m->cellGroup("BAS"));
  const auto top = m->nodesOfCells(m->cellGroup("HAUT"));
  load.imposed.push_back({bottom, 0, model::SpaceFunction(0.0)});
  load.imposed.push_back({bottom, 1, model::SpaceFunction(0.0)});
  load.imposed.push_back({top, 0, model::SpaceFunction(0.02)});
  load.imposed.push_back({top, 1, model::SpaceFunction(-0.015)});
  auto ramp = expr::Expression::compile("INST", {"INST"});
  solver::MechanicalProblem problem;
  problem.model = model;
  problem.materials = materials;
  problem.loads.push_back({&load, ramp});
  problem.kinematics.assign(model->cells().size(), mechanics::Kinematics::TotalLagrangianSVK);
  solver::MechanicalSystem system(problem);
  solver::NewtonSettings settings;
  settings.print = false;
  settings.resiGlobRela = 1e-8;
  settings.method = method;
  solver::StaticNonlinear newton(system, nullptr, settings);
  Eigen::VectorXd U = Eigen::VectorXd::Zero(newton.unknownCount());
  const std::vector<double> times = {0, 0.2, 0.4, 0.6, 0.8, 1.0};
  double rx = 0, ry = 0;
  newton.run(U, times, [&](const solver::ConvergedInstant& c) {
    rx = ry = 0;
    for (int n : top) {
      rx += (*c.reactions)(system.dof(n, 0));
      ry += (*c.reactions)(system.dof(n, 1));
    }
  });
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto& s = newton.statistics();
  std::printf("| %4d | %9d | %3d | %8.2f | %8.2f | %8.2f | %8.0f | %+.7f | %+.7f | %s |\n", N, system.dofCount(),
              s.iterations, total, s.assemblySeconds, s.solveSeconds, peakMegabytes(), rx, ry, method.c_str());
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> sizes;
  std::string method = "UMFPACK";
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--solver") && i + 1 < argc)
      method = argv[++i];
    else
      sizes.push_back(std::atoi(argv[i]));
  }
  if (sizes.empty()) sizes = {64, 128};
  std::printf("| N | DOFs | Newton it. | total s | assembly s | solver s | peak MiB | Rx top | Ry top | solver |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  for (int N : sizes) run(N, method);
}
