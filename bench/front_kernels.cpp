// Microseconds per front of the dense work of one front of the multifrontal factorization
// (factor the m x width front, then its update matrix -L21 L21^T), on one thread, done by
// the BLAS (dpotrf, dtrsm, dsyrk, as the factorization calls them for wider fronts) and by
// each build of the fronts' kernels this CPU runs (linalg/dense_front.hpp), for
// front shapes of the SVK square's elimination tree. Best of 5 runs; the front is copied
// in before each repetition (a memcpy of a few kB).
//   bench_front_kernels [width m ...]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <vector>

#include "linalg/blas_info.hpp"
#include "linalg/dense_front.hpp"

namespace {

using namespace aster::linalg;

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

// The first `width` columns of G G^T + m I, G m x m random: a front before its factorization.
std::vector<double> front(int width, int m) {
  std::mt19937 random(1);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  std::vector<double> G(static_cast<size_t>(m) * m), F(static_cast<size_t>(m) * width);
  for (double& g : G) g = entry(random);
  for (int j = 0; j < width; ++j)
    for (int i = 0; i < m; ++i) {
      double sum = i == j ? m : 0.0;
      for (int k = 0; k < m; ++k) sum += G[i + static_cast<size_t>(k) * m] * G[j + static_cast<size_t>(k) * m];
      F[i + static_cast<size_t>(j) * m] = sum;
    }
  return F;
}

template <class Work>
double microseconds(int reps, Work work) {
  double best = 1e300;
  for (int run = 0; run < 5; ++run) {
    const double t0 = now();
    for (int r = 0; r < reps; ++r) work();
    best = std::min(best, (now() - t0) / reps * 1e6);
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  startBlasOnOneThread();
  selectBlasKernels();
  std::vector<std::pair<int, int>> shapes;
  for (int i = 1; i + 1 < argc; i += 2) shapes.push_back({std::atoi(argv[i]), std::atoi(argv[i + 1])});
  if (shapes.empty())  // widths and heights of the SVK square's fronts, N = 128 and 256
    shapes = {{2, 24},    {10, 43},   {16, 63},    {32, 143},   {64, 237},
              {128, 414}, {128, 1000}, {192, 600}, {512, 1500}, {1500, 3000}};
  const BlasInfo blas = blasInUse();
  std::printf("BLAS: %s (core %s, 1 thread); the factorization uses the %s kernels\n", blas.library.c_str(),
              blas.openblasCore.empty() ? "-" : blas.openblasCore.c_str(), frontKernelsName(frontKernelsInUse()));
  std::vector<FrontKernels> kernels;
  for (FrontKernels k : {FrontKernels::Blas, FrontKernels::Avx2, FrontKernels::Avx512})
    if (frontKernelsRun(k)) kernels.push_back(k);
  std::printf("| width | m | flops |");
  for (FrontKernels k : kernels) std::printf(" %s us | GFLOP/s |", frontKernelsName(k));
  std::printf("\n|---|---|---|");
  for (size_t k = 0; k < kernels.size(); ++k) std::printf("---|---|");
  std::printf("\n");
  for (const auto& [width, m] : shapes) {
    if (width < 1 || m < width) continue;
    const int u = m - width;
    const std::vector<double> F = front(width, m);
    std::vector<double> block(F.size()), U(std::max<size_t>(1, static_cast<size_t>(u) * u));
    std::vector<double> workspace(frontWorkspace(m));
    const double w = width, flops = w * w * w / 3 + u * w * w + static_cast<double>(u) * u * w;
    const int reps = std::max(10, static_cast<int>(1e8 / flops));
    std::printf("| %d | %d | %.3g |", width, m, flops);
    for (FrontKernels k : kernels) {
      const double us = microseconds(reps, [&] {
        std::memcpy(block.data(), F.data(), F.size() * sizeof(double));
        factorFront(width, m, block.data(), workspace.data(), k);
        if (u > 0) updateMatrix(u, width, block.data() + width, m, U.data(), workspace.data(), k);
      });
      std::printf(" %.2f | %.1f |", us, flops / us / 1e3);
    }
    std::printf("\n");
  }
  return 0;
}
