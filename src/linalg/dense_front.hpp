// Dense kernels for the fronts of the multifrontal factorization.
//
// A front is m x width, column-major: its first width rows are the diagonal block A11,
// the others A21. Factorizing it gives L11 L11^T = A11 and L21 = A21 L11^-T in place; its
// update matrix, for its parent, is -L21 L21^T.
//
// Through the BLAS (dpotrf, dtrsm, dsyrk) the thousands of fronts of 2 to 128 columns at
// the bottom of a 2D mesh's elimination tree cost three calls each that pack their
// operands and take a work buffer, and LAPACK's dpotrf goes column by column through
// BLAS-2 calls below 64 columns: fronts of 10 to 16 columns ran at 7-15 GFLOP/s where the
// large ones ran at 45 (SVK square, N = 128). These kernels do the same arithmetic with
// no call and no buffer, by register tiles: the front in panels of kPanel columns, each
// left-looking by blocks of a tile's columns, the products of a panel with the columns
// after it and the update matrix from a packed copy of the rows they read.
//
// Built for AVX2 + FMA (dense_front_avx2.cpp) and for AVX-512 (dense_front_avx512.cpp)
// from one source, and chosen at run time as the element arithmetic is. Every entry of a
// result is the same sequence of fused multiply-adds whatever the build, the panels or
// the pieces a front is cut into: the two builds, on one thread or several, give the same
// bits; they differ from the BLAS's results in rounding only. On a CPU with neither build
// the whole-front functions call the BLAS.
#pragma once
#include <cstddef>

namespace aster::linalg {

enum class FrontKernels { Blas, Avx2, Avx512 };

// Columns of a panel: factorFront goes panel by panel, and so do the front's pieces.
inline constexpr int kFrontPanel = 128;

// The kernels factorizations planned from now on use: the fastest this build and this
// CPU run, unless useFrontKernels chose others (benchmarks compare them). Whether they
// run `kernels`, and their name.
FrontKernels frontKernelsInUse();
void useFrontKernels(FrontKernels kernels);  // throws aster::Error when they do not run here
bool frontKernelsRun(FrontKernels kernels);
const char* frontKernelsName(FrontKernels kernels);

// Doubles of workspace the functions below need for a front (or an update matrix) of `rows` rows.
std::size_t frontWorkspace(int rows);

// The front factorized in place; the entries above L11's diagonal are left as they were.
// Returns 0, or the 1-based column of the first pivot that is not positive (LAPACK's
// info: zero, negative, or NaN, which the BLAS's dpotrf may let through); the columns
// before it are then factorized.
int factorFront(int width, int m, double* block, double* workspace, FrontKernels kernels = frontKernelsInUse());

// U := -L21 L21^T on and below its diagonal (u x u, leading dimension u; nothing above
// the diagonal written), L21 u x width with leading dimension ld.
void updateMatrix(int u, int width, const double* L21, int ld, double* U, double* workspace,
                  FrontKernels kernels = frontKernelsInUse());

// The pieces factorFront and updateMatrix are made of, for a front shared between threads
// (kernels other than the BLAS only):
// - the width x width diagonal block (leading dimension ld) factorized, as factorFront;
int factorDiagonalBlock(int width, int ld, double* diag, FrontKernels kernels);
// - `rows` rows below it (part, leading dimension ld): part := part L11^-T;
void solveRowsBelow(int width, int ld, const double* diag, int rows, double* part, FrontKernels kernels);
// - C(i, j) for c0 <= j < c1, j <= i < rows := (assign ? 0 : C(i, j)) - sum over l < k
//   of A(i, l) A(j, l); nothing above C's diagonal written. workspace: frontWorkspace(rows - c0).
void subtractLowerProducts(int rows, int c0, int c1, int k, const double* A, int lda, double* C, int ldc,
                           double* workspace, bool assign, FrontKernels kernels);

}  // namespace aster::linalg
