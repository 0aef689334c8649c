// Dense kernels for the narrow fronts of the multifrontal factorization.
//
// A 2D mesh's elimination tree has thousands of supernodes of 2 to 32 columns at its
// bottom (SVK square, N = 128: 6 000 of its 6 700 fronts, a quarter of the
// factorization's time). Through the BLAS (dpotrf, dtrsm, dsyrk) each costs three calls
// that pack their operands and take a work buffer, and LAPACK's dpotrf goes column by
// column through BLAS-2 calls below 64 columns: such fronts ran at 7-15 GFLOP/s where
// the large ones run at 45. These kernels do the same arithmetic in two passes over the
// front, with no call and no buffer: the panel factorized column by column (its columns
// stay in L1), and the update matrix by tiles of 8 x 4 kept in registers.
//
// Built for AVX2 + FMA (small_front_avx2.cpp) and chosen at run time, as the element
// arithmetic is; on a CPU without them (smallFrontKernels() false) the functions below
// call the BLAS. The results differ from the BLAS's in rounding only.
#pragma once
#include <cstddef>

namespace aster::linalg {

// Fronts of at most this many columns take these kernels.
inline constexpr int kSmallFrontWidth = 128;

// Whether this build and this CPU run the kernels (AVX2 + FMA) rather than the BLAS.
bool smallFrontKernels();

// The m x width front (column-major, leading dimension m; A11 its first width rows)
// factorized in place: L11 L11^T = A11 (lower), L21 = A21 L11^-T; the entries above
// L11's diagonal are left as they were. Returns 0, or the 1-based column of the first
// pivot that is not positive (LAPACK's info); the columns before it are then factorized.
int smallFrontFactor(int width, int m, double* block);

// U := -L21 L21^T (u x u, leading dimension u: its lower triangle, and perhaps entries
// above the diagonal, which the factorization does not read), L21 u x width with leading
// dimension ld. workspace: at least smallFrontWorkspace(u, width) doubles.
void smallFrontUpdate(int u, int width, const double* L21, int ld, double* U, double* workspace);
std::size_t smallFrontWorkspace(int u, int width);

}  // namespace aster::linalg
