// Dense kernels for the narrow fronts of the multifrontal factorization.
//
// A 2D mesh's elimination tree has thousands of supernodes of 2 to 128 columns (SVK
// square, N = 128: 6 700 of its 6 750 fronts, half of the factorization's time). Through
// the BLAS (dpotrf, dtrsm, dsyrk) each costs three calls that pack their operands and take
// a work buffer, and LAPACK's dpotrf goes column by column through BLAS-2 calls below 64
// columns: fronts of 10 to 16 columns ran at 7-15 GFLOP/s where the large ones run at 45.
// These kernels do the same arithmetic in two passes over the front, with no call and no
// buffer: the front factorized left-looking by blocks of columns (the products of the
// columns before each block by register tiles), and the update matrix by register tiles.
//
// Built for AVX2 + FMA (small_front_avx2.cpp) and for AVX-512 (small_front_avx512.cpp)
// from one source, and chosen at run time as the element arithmetic is. Both builds give
// the same bits (each entry the same sequence of fused multiply-adds); they differ from
// the BLAS's results in rounding only. On a CPU with neither, the functions call the BLAS.
#pragma once
#include <cstddef>

namespace aster::linalg {

// Fronts of at most this many columns take these kernels: beyond, the BLAS's blocked
// routines keep up with them (bench_front_kernels).
inline constexpr int kSmallFrontWidth = 128;

enum class FrontKernels { Blas, Avx2, Avx512 };

// The fastest kernels this build and this CPU run, and whether they run `kernels`.
FrontKernels frontKernelsInUse();
bool frontKernelsRun(FrontKernels kernels);
const char* frontKernelsName(FrontKernels kernels);

// The m x width front (column-major, leading dimension m; A11 its first width rows)
// factorized in place: L11 L11^T = A11 (lower), L21 = A21 L11^-T; the entries above
// L11's diagonal are left as they were. Returns 0, or the 1-based column of the first
// pivot that is not positive (LAPACK's info); the columns before it are then factorized.
int smallFrontFactor(int width, int m, double* block, FrontKernels kernels = frontKernelsInUse());

// U := -L21 L21^T (u x u, leading dimension u: its lower triangle, and perhaps entries
// above the diagonal, which the factorization does not read), L21 u x width with leading
// dimension ld. workspace: at least smallFrontWorkspace(u, width) doubles.
void smallFrontUpdate(int u, int width, const double* L21, int ld, double* U, double* workspace,
                      FrontKernels kernels = frontKernelsInUse());
std::size_t smallFrontWorkspace(int u, int width);

}  // namespace aster::linalg
