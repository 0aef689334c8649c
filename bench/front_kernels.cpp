// Microseconds per front of the dense work of one front of the multifrontal factorization
// (factor the m x width front, then its update matrix -L21 L21^T), on one thread, done by
// the narrow fronts' kernels (linalg/small_front.hpp) and by the BLAS (dpotrf, dtrsm,
// dsyrk, as the factorization calls them for wider fronts), for front shapes of the SVK
// square's elimination tree. Best of 5 runs; the front is copied in before each repetition
// in both (a memcpy of a few kB).
//   bench_front_kernels [width m ...]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <vector>

#include "linalg/blas_info.hpp"
#include "linalg/small_front.hpp"

extern "C" {
void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info);
void dtrsm_(const char* side, const char* uplo, const char* transa, const char* diag, const int* m, const int* n,
            const double* alpha, const double* a, const int* lda, double* b, const int* ldb);
void dsyrk_(const char* uplo, const char* trans, const int* n, const int* k, const double* alpha, const double* a,
            const int* lda, const double* beta, double* c, const int* ldc);
}

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
    shapes = {{2, 24}, {10, 43}, {16, 63}, {32, 143}, {64, 237}, {128, 414}, {128, 1000}, {192, 600}};
  const BlasInfo blas = blasInUse();
  std::printf("BLAS: %s (core %s, 1 thread); narrow-front kernels: %s, widths up to %d\n", blas.library.c_str(),
              blas.openblasCore.empty() ? "-" : blas.openblasCore.c_str(),
              smallFrontKernels() ? "AVX2 + FMA" : "none (the BLAS)", kSmallFrontWidth);
  std::printf("| width | m | flops | kernels us | GFLOP/s | BLAS us | GFLOP/s |\n|---|---|---|---|---|---|---|\n");
  for (const auto& [width, m] : shapes) {
    if (width < 1 || m < width) continue;
    const int u = m - width;
    const std::vector<double> F = front(width, m);
    std::vector<double> block(F.size()), U(std::max<size_t>(1, static_cast<size_t>(u) * u));
    std::vector<double> workspace(smallFrontWorkspace(u, width));
    const double w = width, flops = w * w * w / 3 + u * w * w + static_cast<double>(u) * u * w;
    const int reps = std::max(10, static_cast<int>(1e8 / flops));
    const double kernels = microseconds(reps, [&] {
      std::memcpy(block.data(), F.data(), F.size() * sizeof(double));
      smallFrontFactor(width, m, block.data());
      if (u > 0) smallFrontUpdate(u, width, block.data() + width, m, U.data(), workspace.data());
    });
    const double viaBlas = microseconds(reps, [&] {
      std::memcpy(block.data(), F.data(), F.size() * sizeof(double));
      int info = 0;
      const double one = 1.0, minusOne = -1.0, zero = 0.0;
      dpotrf_("L", &width, block.data(), &m, &info);
      if (u > 0) {
        dtrsm_("R", "L", "T", "N", &u, &width, &one, block.data(), &m, block.data() + width, &m);
        dsyrk_("L", "N", &u, &width, &minusOne, block.data() + width, &m, &zero, U.data(), &u);
      }
    });
    std::printf("| %d | %d | %.3g | %.2f | %.1f | %.2f | %.1f |\n", width, m, flops, kernels,
                flops / kernels / 1e3, viaBlas, flops / viaBlas / 1e3);
  }
  return 0;
}
