// The kernels of narrow fronts (small_front.hpp) compiled with -mavx2 -mfma
// (src/CMakeLists.txt). Plain loops and intrinsics only: no inline function of a library
// header is instantiated here, so no AVX2 copy of one can reach the baseline code through
// the linker (tests/avx2_symbols.cmake checks it).
#ifdef ASTER_AVX2_FRONTS
#if !defined(__AVX2__) || !defined(__FMA__)
#error "small_front_avx2.cpp must be compiled with -mavx2 -mfma (see src/CMakeLists.txt)"
#endif
#include "linalg/small_front_avx2.hpp"

#include <immintrin.h>

#include <cstddef>

namespace aster::linalg::avx2 {

namespace {

// Lanes of a 4-wide load or store that are below `count` (0 to 4).
__m256i firstLanes(int count) {
  return _mm256_cmpgt_epi64(_mm256_set1_epi64x(count), _mm256_set_epi64x(3, 2, 1, 0));
}

// C(0:rows, 0:4) -= A(0:rows, 0:k) B(0:4, 0:k)^T, all column-major with leading dimension
// ld, by tiles of 8 rows x 4 columns kept in registers. A's columns are read 8 rows at a
// time, past `rows` in the last tile: the caller's A is followed by more of its block. C's
// last tile is read and written through masks.
void subtractProducts(int rows, int k, const double* a, const double* b, double* c, int ld) {
  for (int i0 = 0; i0 < rows; i0 += 8) {
    const int left = rows - i0;
    const __m256i low = firstLanes(left < 4 ? left : 4), high = firstLanes(left < 8 ? left - 4 : 4);
    double* out = c + i0;
    const std::size_t l1 = ld, l2 = 2 * l1, l3 = 3 * l1;
    __m256d c00, c01, c02, c03, c10, c11, c12, c13;
    if (left >= 8) {
      c00 = _mm256_loadu_pd(out), c10 = _mm256_loadu_pd(out + 4);
      c01 = _mm256_loadu_pd(out + l1), c11 = _mm256_loadu_pd(out + l1 + 4);
      c02 = _mm256_loadu_pd(out + l2), c12 = _mm256_loadu_pd(out + l2 + 4);
      c03 = _mm256_loadu_pd(out + l3), c13 = _mm256_loadu_pd(out + l3 + 4);
    } else {
      c00 = _mm256_maskload_pd(out, low), c10 = _mm256_maskload_pd(out + 4, high);
      c01 = _mm256_maskload_pd(out + l1, low), c11 = _mm256_maskload_pd(out + l1 + 4, high);
      c02 = _mm256_maskload_pd(out + l2, low), c12 = _mm256_maskload_pd(out + l2 + 4, high);
      c03 = _mm256_maskload_pd(out + l3, low), c13 = _mm256_maskload_pd(out + l3 + 4, high);
    }
    const double* x = a + i0;
    const double* y = b;
    for (int kk = 0; kk < k; ++kk, x += ld, y += ld) {
      const __m256d x0 = _mm256_loadu_pd(x), x1 = _mm256_loadu_pd(x + 4);
      __m256d yk = _mm256_broadcast_sd(y);
      c00 = _mm256_fnmadd_pd(x0, yk, c00);
      c10 = _mm256_fnmadd_pd(x1, yk, c10);
      yk = _mm256_broadcast_sd(y + 1);
      c01 = _mm256_fnmadd_pd(x0, yk, c01);
      c11 = _mm256_fnmadd_pd(x1, yk, c11);
      yk = _mm256_broadcast_sd(y + 2);
      c02 = _mm256_fnmadd_pd(x0, yk, c02);
      c12 = _mm256_fnmadd_pd(x1, yk, c12);
      yk = _mm256_broadcast_sd(y + 3);
      c03 = _mm256_fnmadd_pd(x0, yk, c03);
      c13 = _mm256_fnmadd_pd(x1, yk, c13);
    }
    if (left >= 8) {
      _mm256_storeu_pd(out, c00), _mm256_storeu_pd(out + 4, c10);
      _mm256_storeu_pd(out + l1, c01), _mm256_storeu_pd(out + l1 + 4, c11);
      _mm256_storeu_pd(out + l2, c02), _mm256_storeu_pd(out + l2 + 4, c12);
      _mm256_storeu_pd(out + l3, c03), _mm256_storeu_pd(out + l3 + 4, c13);
    } else {
      _mm256_maskstore_pd(out, low, c00), _mm256_maskstore_pd(out + 4, high, c10);
      _mm256_maskstore_pd(out + l1, low, c01), _mm256_maskstore_pd(out + l1 + 4, high, c11);
      _mm256_maskstore_pd(out + l2, low, c02), _mm256_maskstore_pd(out + l2 + 4, high, c12);
      _mm256_maskstore_pd(out + l3, low, c03), _mm256_maskstore_pd(out + l3 + 4, high, c13);
    }
  }
}

}  // namespace

// Left-looking by blocks of 4 columns: each block's rows from its diagonal down first
// take the products of the columns before it (subtractProducts, where the flops are),
// then its own columns are factorized one after the other, right-looking within the
// block. The front is a few dozen rows by at most 32 columns and stays in L1.
int frontFactor(int width, int m, double* block) {
  for (int j0 = 0; j0 < width; j0 += 4) {
    const int end = j0 + 4 < width ? j0 + 4 : width;
    double* corner = block + j0 + static_cast<std::size_t>(j0) * m;
    if (j0 > 0) {
      if (end - j0 == 4) {
        // The tile also changes the 6 entries above the block's diagonal, L11's upper
        // triangle, which is left as it was (as dpotrf leaves it).
        const double above[6] = {corner[m], corner[2 * m], corner[2 * m + 1],
                                 corner[3 * m], corner[3 * m + 1], corner[3 * m + 2]};
        // Rows j0.. of the columns before the block: followed in memory by the next column.
        subtractProducts(m - j0, j0, block + j0, block + j0, corner, m);
        corner[m] = above[0], corner[2 * m] = above[1], corner[2 * m + 1] = above[2];
        corner[3 * m] = above[3], corner[3 * m + 1] = above[4], corner[3 * m + 2] = above[5];
      } else {
        for (int j = j0; j < end; ++j) {
          double* __restrict target = block + static_cast<std::size_t>(j) * m;
          for (int k = 0; k < j0; ++k) {
            const double* __restrict column = block + static_cast<std::size_t>(k) * m;
            const double f = column[j];
            for (int i = j; i < m; ++i) target[i] -= column[i] * f;
          }
        }
      }
    }
    for (int j = j0; j < end; ++j) {
      double* __restrict column = block + static_cast<std::size_t>(j) * m;
      const double d = column[j];
      if (!(d > 0.0)) return j + 1;  // not positive, or NaN
      const double l = __builtin_sqrt(d);
      column[j] = l;
      const double scale = 1.0 / l;
      for (int i = j + 1; i < m; ++i) column[i] *= scale;
      for (int k = j + 1; k < end; ++k) {
        double* __restrict target = block + static_cast<std::size_t>(k) * m;
        const double f = column[k];
        for (int i = k; i < m; ++i) target[i] -= column[i] * f;
      }
    }
  }
  return 0;
}

// L21 is first copied, its columns padded with zeros to packedRows(u) rows, so that every
// tile reads whole vectors. Then U by tiles of 8 rows x 4 columns, each the sum over the
// width of 8 x 4 products kept in eight registers; the tiles of each block of 4 columns
// start at its diagonal, whose tile also writes a few entries above the diagonal (they
// are U's upper triangle's, which is not read).
void frontUpdate(int u, int width, const double* L21, int ld, double* U, double* packed) {
  const int rows = packedRows(u);
  for (int k = 0; k < width; ++k) {
    const double* from = L21 + static_cast<std::size_t>(k) * ld;
    double* to = packed + static_cast<std::size_t>(k) * rows;
    for (int i = 0; i < u; ++i) to[i] = from[i];
    for (int i = u; i < rows; ++i) to[i] = 0.0;
  }
  for (int j0 = 0; j0 < u; j0 += 4) {
    const int columns = u - j0 < 4 ? u - j0 : 4;
    for (int i0 = j0; i0 < u; i0 += 8) {
      __m256d c00 = _mm256_setzero_pd(), c01 = c00, c02 = c00, c03 = c00;
      __m256d c10 = c00, c11 = c00, c12 = c00, c13 = c00;
      const double* a = packed + i0;
      const double* b = packed + j0;
      for (int k = 0; k < width; ++k, a += rows, b += rows) {
        const __m256d a0 = _mm256_loadu_pd(a), a1 = _mm256_loadu_pd(a + 4);
        __m256d bk = _mm256_broadcast_sd(b);
        c00 = _mm256_fnmadd_pd(a0, bk, c00);
        c10 = _mm256_fnmadd_pd(a1, bk, c10);
        bk = _mm256_broadcast_sd(b + 1);
        c01 = _mm256_fnmadd_pd(a0, bk, c01);
        c11 = _mm256_fnmadd_pd(a1, bk, c11);
        bk = _mm256_broadcast_sd(b + 2);
        c02 = _mm256_fnmadd_pd(a0, bk, c02);
        c12 = _mm256_fnmadd_pd(a1, bk, c12);
        bk = _mm256_broadcast_sd(b + 3);
        c03 = _mm256_fnmadd_pd(a0, bk, c03);
        c13 = _mm256_fnmadd_pd(a1, bk, c13);
      }
      double* out = U + i0 + static_cast<std::size_t>(j0) * u;
      if (u - i0 >= 8 && columns == 4) {
        _mm256_storeu_pd(out, c00);
        _mm256_storeu_pd(out + 4, c10);
        _mm256_storeu_pd(out + u, c01);
        _mm256_storeu_pd(out + u + 4, c11);
        _mm256_storeu_pd(out + 2 * static_cast<std::size_t>(u), c02);
        _mm256_storeu_pd(out + 2 * static_cast<std::size_t>(u) + 4, c12);
        _mm256_storeu_pd(out + 3 * static_cast<std::size_t>(u), c03);
        _mm256_storeu_pd(out + 3 * static_cast<std::size_t>(u) + 4, c13);
        continue;
      }
      alignas(32) double tile[4][8];  // the last rows or columns: through a copy
      _mm256_store_pd(tile[0], c00);
      _mm256_store_pd(tile[0] + 4, c10);
      _mm256_store_pd(tile[1], c01);
      _mm256_store_pd(tile[1] + 4, c11);
      _mm256_store_pd(tile[2], c02);
      _mm256_store_pd(tile[2] + 4, c12);
      _mm256_store_pd(tile[3], c03);
      _mm256_store_pd(tile[3] + 4, c13);
      const int tileRows = u - i0 < 8 ? u - i0 : 8;
      for (int c = 0; c < columns; ++c)
        for (int r = 0; r < tileRows; ++r) out[r + static_cast<std::size_t>(c) * u] = tile[c][r];
    }
  }
}

}  // namespace aster::linalg::avx2
#endif
