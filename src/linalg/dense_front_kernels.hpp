// The kernels of dense_front.hpp, built for AVX2 + FMA (dense_front_avx2.cpp) and for
// AVX-512 (dense_front_avx512.cpp) from one source (dense_front_kernels.inc).
#pragma once
#include "linalg/dense_front.hpp"

namespace aster::linalg {

// Columns of the products a packed copy holds at a time.
inline constexpr int kDepth = 256;

// Rows of a packed copy of `rows` rows: rounded up to 16 (a tile's rows in either build),
// and 16 more, zero.
inline int packedRows(int rows) { return ((rows + 15) / 16) * 16 + 16; }

#define ASTER_DENSE_FRONT_KERNELS                                                                                 \
  int factorDiagonal(int width, int ld, double* diag);                                                            \
  void solveRows(int width, int ld, const double* diag, int rows, double* part);                                  \
  void subtractLowerProducts(int rows, int c0, int c1, int k, const double* A, int lda, double* C, int ldc,       \
                             double* packed, bool assign);                                                        \
  int frontFactor(int width, int m, double* block, double* packed);

namespace avx2 {
ASTER_DENSE_FRONT_KERNELS
}  // namespace avx2

namespace avx512 {
ASTER_DENSE_FRONT_KERNELS
}  // namespace avx512

#undef ASTER_DENSE_FRONT_KERNELS

}  // namespace aster::linalg
