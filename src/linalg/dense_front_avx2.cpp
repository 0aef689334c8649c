// The fronts' kernels (dense_front_kernels.inc) compiled with -mavx2 -mfma
// (src/CMakeLists.txt): vectors of 4 doubles, tiles of 8 x 4. Intrinsics and functions of
// internal linkage only: no inline function of a library header is instantiated here, so
// no AVX2 copy of one can reach the baseline code through the linker
// (tests/simd_symbols.cmake checks it).
#ifdef ASTER_AVX2_FRONTS
#if !defined(__AVX2__) || !defined(__FMA__)
#error "dense_front_avx2.cpp must be compiled with -mavx2 -mfma (see src/CMakeLists.txt)"
#endif
#include <immintrin.h>

#include <cstddef>

#include "linalg/dense_front_kernels.hpp"

namespace aster::linalg::avx2 {

namespace {
using Vec = __m256d;
constexpr int kLanes = 4;
constexpr int kColumns = 4;
inline Vec zero() { return _mm256_setzero_pd(); }
inline Vec load(const double* p) { return _mm256_loadu_pd(p); }
inline void store(double* p, Vec v) { _mm256_storeu_pd(p, v); }
inline __m256i lanesBelow(int n) { return _mm256_cmpgt_epi64(_mm256_set1_epi64x(n), _mm256_set_epi64x(3, 2, 1, 0)); }
inline Vec loadFirst(const double* p, int n) { return n == kLanes ? load(p) : _mm256_maskload_pd(p, lanesBelow(n)); }
inline void storeLanes(double* p, int from, int to, Vec v) {
  if (from == 0 && to == kLanes)
    store(p, v);
  else if (from < to)
    _mm256_maskstore_pd(p, _mm256_andnot_si256(lanesBelow(from), lanesBelow(to)), v);
}
inline Vec broadcast(double x) { return _mm256_set1_pd(x); }
inline Vec minusProductPlus(Vec a, Vec b, Vec c) { return _mm256_fnmadd_pd(a, b, c); }
}  // namespace

#include "linalg/dense_front_kernels.inc"

}  // namespace aster::linalg::avx2
#endif
