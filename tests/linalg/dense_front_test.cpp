#include "linalg/dense_front.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"

namespace aster::linalg {
namespace {

// The first `width` columns of an m x m symmetric positive definite matrix B = G G^T + m I
// (G random in [-1, 1]), column-major with leading dimension m: a front before its
// factorization. B is returned whole.
std::vector<double> spdMatrix(int m, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  std::vector<double> G(static_cast<size_t>(m) * m), B(G.size());
  for (double& g : G) g = entry(random);
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      double sum = i == j ? m : 0.0;
      for (int k = 0; k < m; ++k) sum += G[i + static_cast<size_t>(k) * m] * G[j + static_cast<size_t>(k) * m];
      B[i + static_cast<size_t>(j) * m] = sum;
    }
  return B;
}

// Every build of the kernels this CPU runs, the BLAS included.
std::vector<FrontKernels> runnableKernels() {
  std::vector<FrontKernels> kernels;
  for (FrontKernels k : {FrontKernels::Blas, FrontKernels::Avx2, FrontKernels::Avx512})
    if (frontKernelsRun(k)) kernels.push_back(k);
  return kernels;
}

struct Shape {
  int width, m;
};
// Widths around the tiles (4 and 8 columns, 8 and 16 rows), the panels (kFrontPanel
// columns) and the packed copies (256 columns at a time).
const Shape kShapes[] = {{1, 1},    {1, 9},     {2, 2},     {3, 12},    {4, 4},     {4, 13},    {5, 5},
                         {5, 17},   {7, 30},    {8, 8},     {8, 16},    {9, 40},    {12, 20},   {16, 63},
                         {17, 18},  {31, 70},   {33, 100},  {64, 237},  {100, 101}, {128, 300}, {129, 140},
                         {200, 450}, {260, 261}, {300, 700}};

// The factorized front reproduces the front: L11 L11^T = B11 and L21 L11^T = B21, to the
// rounding of sums of `width` products of entries of size about sqrt(m). The entries above
// L11's diagonal are not touched (the solves and CHOLMOD's storage expect them as given).
TEST(DenseFront, FactorReproducesTheFront) {
  const double mark = 7.25;
  for (const FrontKernels kernels : runnableKernels())
  for (const Shape& s : kShapes) {
    const int w = s.width, m = s.m;
    const std::vector<double> B = spdMatrix(m, 7 + w + m);
    std::vector<double> L(B.begin(), B.begin() + static_cast<size_t>(m) * w);
    for (int j = 0; j < w; ++j)
      for (int i = 0; i < j; ++i) L[i + static_cast<size_t>(j) * m] = mark;
    SCOPED_TRACE(std::string(frontKernelsName(kernels)) + ", " + std::to_string(w) + " x " + std::to_string(m));
    std::vector<double> workspace(frontWorkspace(m));
    ASSERT_EQ(factorFront(w, m, L.data(), workspace.data(), kernels), 0);
    for (int j = 0; j < w; ++j)
      for (int i = 0; i < j; ++i) ASSERT_EQ(L[i + static_cast<size_t>(j) * m], mark);
    double largest = 0.0, error = 0.0;
    for (int j = 0; j < w; ++j)
      for (int i = j; i < m; ++i) {
        double sum = 0.0;  // (L L^T)(i, j), both factors from the lower trapezoid
        for (int k = 0; k <= j; ++k) sum += L[i + static_cast<size_t>(k) * m] * L[j + static_cast<size_t>(k) * m];
        const double b = B[i + static_cast<size_t>(j) * m];
        largest = std::max(largest, std::abs(b));
        error = std::max(error, std::abs(sum - b));
      }
    EXPECT_LE(error, 64 * std::numeric_limits<double>::epsilon() * largest);
    for (int j = 0; j < w; ++j) EXPECT_GT(L[j + static_cast<size_t>(j) * m], 0.0);
  }
}

// The update matrix is -L21 L21^T on and below its diagonal, summed here directly, and
// nothing is written above the diagonal.
TEST(DenseFront, UpdateIsMinusL21L21Transposed) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  const double mark = -3.5;
  for (const FrontKernels kernels : runnableKernels())
  for (const Shape& s : kShapes) {
    const int w = s.width, u = s.m - s.width, ld = s.m + 3;  // L21 inside a larger block
    if (u == 0) continue;
    std::vector<double> L21(static_cast<size_t>(ld) * w), U(static_cast<size_t>(u) * u, mark);
    for (double& x : L21) x = entry(random);
    std::vector<double> workspace(frontWorkspace(u));
    updateMatrix(u, w, L21.data(), ld, U.data(), workspace.data(), kernels);
    double error = 0.0;
    for (int j = 0; j < u; ++j) {
      for (int i = 0; i < j; ++i) ASSERT_EQ(U[i + static_cast<size_t>(j) * u], mark) << frontKernelsName(kernels);
      for (int i = j; i < u; ++i) {
        double sum = 0.0;
        for (int k = 0; k < w; ++k) sum -= L21[i + static_cast<size_t>(k) * ld] * L21[j + static_cast<size_t>(k) * ld];
        error = std::max(error, std::abs(U[i + static_cast<size_t>(j) * u] - sum));
      }
    }
    EXPECT_LE(error, 4 * w * std::numeric_limits<double>::epsilon()) << frontKernelsName(kernels) << ", " << w << " x " << u;
  }
}

// A front cut into pieces as the threads share it (each panel's diagonal block, its rows
// below in slices, its products with the next columns in slices of those columns; the
// update matrix in slices of its columns) gives the same bits as the whole front.
TEST(DenseFront, PiecesGiveTheBitsOfTheWholeFront) {
  for (const FrontKernels kernels : runnableKernels()) {
    if (kernels == FrontKernels::Blas) continue;
    for (const Shape& s : {Shape{200, 450}, Shape{300, 700}, Shape{40, 90}}) {
      const int w = s.width, m = s.m, u = m - w;
      SCOPED_TRACE(std::string(frontKernelsName(kernels)) + ", " + std::to_string(w) + " x " + std::to_string(m));
      const std::vector<double> B = spdMatrix(m, 17 + w);
      std::vector<double> whole(B.begin(), B.begin() + static_cast<size_t>(m) * w), pieces = whole;
      std::vector<double> workspace(frontWorkspace(m));
      ASSERT_EQ(factorFront(w, m, whole.data(), workspace.data(), kernels), 0);
      for (int p0 = 0; p0 < w; p0 += kFrontPanel) {
        const int b = std::min(kFrontPanel, w - p0), below = m - p0 - b, trailing = w - p0 - b;
        double* panel = pieces.data() + p0 + static_cast<size_t>(p0) * m;
        ASSERT_EQ(factorDiagonalBlock(b, m, panel, kernels), 0);
        for (const auto& [r0, r1] : {std::pair{0, below / 3}, std::pair{below / 3, below / 2}, std::pair{below / 2, below}})
          if (r1 > r0) solveRowsBelow(b, m, panel, r1 - r0, panel + b + r0, kernels);
        for (const auto& [c0, c1] : {std::pair{0, trailing / 4}, std::pair{trailing / 4, trailing}})
          if (c1 > c0)
            subtractLowerProducts(below, c0, c1, b, panel + b, m, panel + b + static_cast<size_t>(b) * m, m,
                                  workspace.data(), false, kernels);
      }
      EXPECT_EQ(pieces, whole);
      std::vector<double> Uwhole(static_cast<size_t>(u) * u, 0.0), Upieces = Uwhole;
      updateMatrix(u, w, whole.data() + w, m, Uwhole.data(), workspace.data(), kernels);
      for (const auto& [c0, c1] : {std::pair{0, 13}, std::pair{13, u / 2}, std::pair{u / 2, u}})
        subtractLowerProducts(u, c0, c1, w, whole.data() + w, m, Upieces.data(), u, workspace.data(), true, kernels);
      EXPECT_EQ(Upieces, Uwhole);
    }
  }
}

// A pivot that is not positive stops the factorization at its column, 1-based, as
// LAPACK's dpotrf reports it: zero, negative, or NaN (which OpenBLAS's dpotrf lets
// through: the BLAS path is not asked for it).
TEST(DenseFront, NonPositivePivotNamesItsColumn) {
  const int w = 9, m = 20;
  for (const FrontKernels kernels : runnableKernels())
  for (const double bad : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN()}) {
    if (std::isnan(bad) && kernels == FrontKernels::Blas) continue;
    std::vector<double> B = spdMatrix(m, 11);
    // Column 6 (0-based 5) made a copy of column 3 (0-based 2) over the front: B11 becomes
    // singular at its sixth pivot, which is then zero up to rounding; set it exactly.
    std::vector<double> L(B.begin(), B.begin() + static_cast<size_t>(m) * w);
    for (int i = 0; i < m; ++i) L[i + 5 * static_cast<size_t>(m)] = 0.0;
    for (int j = 0; j < w; ++j) L[5 + static_cast<size_t>(j) * m] = 0.0;
    L[5 + 5 * static_cast<size_t>(m)] = bad;  // the sixth pivot is then exactly `bad`
    std::vector<double> workspace(frontWorkspace(m));
    EXPECT_EQ(factorFront(w, m, L.data(), workspace.data(), kernels), 6) << frontKernelsName(kernels) << ", pivot " << bad;
  }
}

// The AVX2 and AVX-512 builds give the same bits, so that results do not depend on which
// of the two a CPU runs (each entry is the same sequence of fused multiply-adds).
TEST(DenseFront, Avx2AndAvx512GiveTheSameBits) {
  if (!frontKernelsRun(FrontKernels::Avx2) || !frontKernelsRun(FrontKernels::Avx512))
    GTEST_SKIP() << "this build or CPU runs only one of them";
  for (const Shape& s : kShapes) {
    const int w = s.width, m = s.m, u = m - w;
    const std::vector<double> B = spdMatrix(m, 5 + w + m);
    std::vector<double> L2(B.begin(), B.begin() + static_cast<size_t>(m) * w), L512 = L2;
    std::vector<double> workspace(frontWorkspace(m));
    ASSERT_EQ(factorFront(w, m, L2.data(), workspace.data(), FrontKernels::Avx2), 0);
    ASSERT_EQ(factorFront(w, m, L512.data(), workspace.data(), FrontKernels::Avx512), 0);
    EXPECT_EQ(L2, L512) << w << " x " << m;
    if (u == 0) continue;
    std::vector<double> U2(static_cast<size_t>(u) * u, 0.0), U512 = U2;
    updateMatrix(u, w, L2.data() + w, m, U2.data(), workspace.data(), FrontKernels::Avx2);
    updateMatrix(u, w, L2.data() + w, m, U512.data(), workspace.data(), FrontKernels::Avx512);
    EXPECT_EQ(U2, U512) << w << " x " << m;
  }
}

// A build this CPU does not run is refused by name, never run.
TEST(DenseFront, KernelsThisCpuDoesNotRunAreRefused) {
  for (const FrontKernels kernels : {FrontKernels::Avx2, FrontKernels::Avx512}) {
    if (frontKernelsRun(kernels)) continue;
    double pivot = 4.0, workspace[64];
    EXPECT_THROW(factorFront(1, 1, &pivot, workspace, kernels), Error) << frontKernelsName(kernels);
  }
  double pivot = 4.0;
  EXPECT_THROW(factorDiagonalBlock(1, 1, &pivot, FrontKernels::Blas), Error);  // pieces: the kernels only
  EXPECT_TRUE(frontKernelsRun(frontKernelsInUse()));
}

}  // namespace
}  // namespace aster::linalg
