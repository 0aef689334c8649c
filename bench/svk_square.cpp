// The SVK square benchmark: a regular N x N QUAD8 mesh of the unit square,
// plane strain, E = 1, NU = 0.3, Saint Venant-Kirchhoff (GROT_GDEP), bottom
// clamped, top displaced by (0.02, -0.015) in 5 equal increments, Newton to
// RESI_GLOB_RELA = 1e-8. Prints DOFs, Newton iterations, seconds (total,
// assembly, linear solver), peak memory and the final reaction on the top edge
// (force of the support on the body), to compare with other programs.
// Also: the ordering and flops of the factorization, its rate (flops of one factorization
// over the mean time of one; and over the mean time of those after the first, which also
// gets the factor's memory from the system), and the rate of a dense dgemm with the BLAS linked.
// With --csv or --solver GCPC, a '#' line adds the counts (GCPC: the preconditioner's
// factorizations, the conjugate gradient's iterations per Newton solve) and Ry to 12 digits.
//   bench_svk_square [N ...] [--solver MULT_FRONT|MUMPS|GCPC|UMFPACK|CHOLMOD|KLU|EIGEN_LU]
//                    [--prediction TANGENTE|EXTRAPOLE] [--front-kernels BLAS|AVX2|AVX512]
//                    [--dgemm n] [--csv]
// --front-kernels: the multifrontal factorization's dense work by the BLAS or by one build
// of its own kernels (linalg/dense_front.hpp; default: the fastest the CPU runs).
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "support/square_mesh.hpp"
#include "expr/expression.hpp"
#include "linalg/blas_info.hpp"
#include "linalg/dense_front.hpp"
#include "linalg/factor_memory.hpp"
#include "analysis/convergence_table.hpp"
#include "analysis/static_nonlinear.hpp"

using namespace aster;

extern "C" void dgemm_(const char*, const char*, const int*, const int*, const int*, const double*, const double*,
                       const int*, const double*, const int*, const double*, double*, const int*);

namespace {

bool csv = false;
bool extrapolate = false;

// GFLOP/s of C = A B with n x n matrices, best of 5 (the machine is shared).
double dgemmRate(int n) {
  std::vector<double> a(static_cast<size_t>(n) * n), b(a.size()), c(a.size());
  for (size_t i = 0; i < a.size(); ++i) {
    a[i] = 1.0 / (1 + i % 97);
    b[i] = 1.0 / (1 + i % 89);
  }
  const double one = 1, zero = 0;
  double best = 0;
  for (int r = 0; r < 5; ++r) {
    const auto t = std::chrono::steady_clock::now();
    dgemm_("N", "N", &n, &n, &n, &one, a.data(), &n, b.data(), &n, &zero, c.data(), &n);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    best = std::max(best, 2.0 * n * n * static_cast<double>(n) / s / 1e9);
  }
  return best;
}

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
  analysis::MechanicalProblem problem;
  problem.model = model;
  problem.materials = materials;
  problem.loads.push_back({&load, ramp});
  problem.kinematics.assign(model->cells().size(), mechanics::Kinematics::GreenLagrange);
  analysis::MechanicalSystem system(problem);
  analysis::NewtonSettings settings;
  settings.resiGlobRela = 1e-8;
  settings.method = method;
  if (extrapolate) settings.prediction = analysis::Prediction::Extrapolated;
  analysis::StaticNonlinear newton(system, nullptr, settings);
  analysis::ConvergenceTable table(false);
  if (getenv("NEWTON_PRINT")) newton.addObserver(table);
  Eigen::VectorXd U = Eigen::VectorXd::Zero(newton.unknownCount());
  const std::vector<double> times = {0, 0.2, 0.4, 0.6, 0.8, 1.0};
  double rx = 0, ry = 0;
  newton.run(U, times, [&](const analysis::ConvergedInstant& c) {
    rx = ry = 0;
    for (int n : top) {
      rx += (*c.reactions)(system.dof(n, 0));
      ry += (*c.reactions)(system.dof(n, 1));
    }
  });
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto& s = newton.statistics();
  const auto& ls = newton.solverStatistics();
  const double perFactorization = ls.factorizeCount ? (ls.numericSeconds > 0 ? ls.numericSeconds : ls.factorizeSeconds) / ls.factorizeCount : 0.0;
  const double gflops = ls.factorFlops > 0 && perFactorization > 0 ? ls.factorFlops / perFactorization / 1e9 : 0.0;
  // Without the first factorization, which also gets the factor's memory from the system.
  const double perLater = ls.factorizeCount > 1 && ls.numericSeconds > 0
                              ? (ls.numericSeconds - ls.firstNumericSeconds) / (ls.factorizeCount - 1)
                              : perFactorization;
  const double laterGflops = ls.factorFlops > 0 && perLater > 0 ? ls.factorFlops / perLater / 1e9 : 0.0;
  if (csv)
    std::printf("%d,%d,%d,%.3f,%.3f,%.3f,%.3f,%.3f,%d,%.4g,%.2f,%.2f,%.0f,%.8g,%.8g,%s,%s\n", N, system.dofCount(),
                s.iterations, total, s.assemblySeconds, s.solveSeconds, ls.analyzeSeconds, ls.factorizeSeconds,
                ls.factorizeCount, ls.factorFlops, gflops, laterGflops, peakMegabytes(), rx, ry, method.c_str(),
                ls.ordering.empty() ? "-" : ls.ordering.c_str());
  else
    std::printf("| %4d | %9d | %3d | %8.2f | %8.2f | %8.2f | %8.2f | %9.3g | %6.1f | %6.1f | %8.0f | %+.7f | %+.7f | %s %s |\n",
                N, system.dofCount(), s.iterations, total, s.assemblySeconds, s.solveSeconds, ls.factorizeSeconds,
                ls.factorFlops, gflops, laterGflops, peakMegabytes(), rx, ry, method.c_str(), ls.ordering.c_str());
  // A comment line (bench/run skips it): the counts, and Ry to 12 digits to compare solvers.
  if (csv || method == "GCPC") {
    std::printf("# N = %d %s: %d Newton iterations, %d matrices factorized by the driver, %d factorizations",
                N, method.c_str(), s.iterations, s.factorizations, ls.factorizeCount);
    if (method == "GCPC")
      std::printf(" (of the preconditioner), %lld conjugate gradient iterations over %d solves (%.2f per solve)",
                  ls.krylovIterations, ls.solveCount,
                  ls.solveCount ? static_cast<double>(ls.krylovIterations) / ls.solveCount : 0.0);
    std::printf(", Ry = %.12g\n", ry);
  }
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  linalg::startBlasOnOneThread();
  linalg::selectBlasKernels();
  linalg::keepFactorWorkspaces();
  std::vector<int> sizes;
  std::string method = "CHOLMOD";
  int dgemmSize = 0;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--solver") && i + 1 < argc)
      method = argv[++i];
    else if (!std::strcmp(argv[i], "--dgemm") && i + 1 < argc)
      dgemmSize = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--prediction") && i + 1 < argc)
      extrapolate = !std::strcmp(argv[++i], "EXTRAPOLE");
    else if (!std::strcmp(argv[i], "--front-kernels") && i + 1 < argc) {
      const std::string name = argv[++i];
      linalg::useFrontKernels(name == "BLAS" ? linalg::FrontKernels::Blas
                              : name == "AVX2" ? linalg::FrontKernels::Avx2
                                               : linalg::FrontKernels::Avx512);
    } else if (!std::strcmp(argv[i], "--csv"))
      csv = true;
    else if (std::atoi(argv[i]) >= 1)
      sizes.push_back(std::atoi(argv[i]));
    else {
      std::fprintf(stderr, "usage: bench_svk_square [N ...] [--solver METHODE] [--prediction TANGENTE|EXTRAPOLE] "
                           "[--front-kernels BLAS|AVX2|AVX512] [--dgemm n] [--csv]\n");
      return !std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h") ? 0 : 2;
    }
  }
  const linalg::BlasInfo blas = linalg::blasInUse();
  std::printf("%s BLAS: %s (%s, core %s, %d threads); front kernels: %s\n", csv ? "#" : "", blas.library.c_str(),
              blas.openblasConfig.empty() ? "-" : blas.openblasConfig.c_str(),
              blas.openblasCore.empty() ? "-" : blas.openblasCore.c_str(), linalg::startupBlasThreads(),
              linalg::frontKernelsName(linalg::frontKernelsInUse()));
  if (dgemmSize > 0) {
    // Every thread OpenBLAS would use, although the process started it on one.
    const linalg::ScopedBlasThreads all(linalg::startupBlasThreads());
    std::printf("%s dgemm n=%d: %.1f GFLOP/s\n", csv ? "#" : "", dgemmSize, dgemmRate(dgemmSize));
  }
  if (csv) {
    std::printf("N,dofs,newton,total_s,assembly_s,solve_s,analyze_s,factorize_s,factorizations,factor_flops,"
                "factor_gflops,later_gflops,peak_mib,rx,ry,solver,ordering\n");
  } else {
    std::printf("| N | DOFs | Newton it. | total s | assembly s | solver s | factorize s | flops/fact. | GFLOP/s | "
                "GFLOP/s after the first | peak MiB | Rx top | Ry top | solver |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  }
  std::fflush(stdout);
  if (sizes.empty() && dgemmSize > 0) return 0;  // the dense rate only
  for (int N : sizes.empty() ? std::vector<int>{64, 128} : sizes) {
    try {
      run(N, method);
    } catch (const std::exception& e) {  // a solver that cannot take N (UMFPACK's memory at 512)
      std::fflush(stdout);
      std::fprintf(stderr, "N = %d, %s: %s\n", N, method.c_str(), e.what());
      return 1;
    }
  }
}
