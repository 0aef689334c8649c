// The fronts' kernels (dense_front_kernels.inc) compiled with -mavx512f, and -mavx2 -mfma
// so that the loops the compiler vectorizes on 4 lanes fuse their multiply-adds as the
// AVX2 build does (src/CMakeLists.txt): vectors of 8 doubles, tiles of 16 x 8. On a CPU
// with full-width AVX-512 units (AMD Zen 5, Intel's servers) they run at twice the AVX2
// build's rate on large fronts. Same rules as dense_front_avx2.cpp (tests/simd_symbols.cmake).
#ifdef ASTER_AVX512_FRONTS
#if !defined(__AVX512F__) || !defined(__AVX2__) || !defined(__FMA__)
#error "dense_front_avx512.cpp must be compiled with -mavx2 -mfma -mavx512f (see src/CMakeLists.txt)"
#endif
#include <immintrin.h>

#include <cstddef>

#include "linalg/dense_front_kernels.hpp"

namespace aster::linalg::avx512 {

namespace {
using Vec = __m512d;
constexpr int kLanes = 8;
constexpr int kColumns = 8;
inline Vec zero() { return _mm512_setzero_pd(); }
inline Vec load(const double* p) { return _mm512_loadu_pd(p); }
inline void store(double* p, Vec v) { _mm512_storeu_pd(p, v); }
inline __mmask8 lanesBelow(int n) { return static_cast<__mmask8>((1u << n) - 1u); }
inline Vec loadFirst(const double* p, int n) { return _mm512_maskz_loadu_pd(lanesBelow(n), p); }
inline void storeLanes(double* p, int from, int to, Vec v) {
  _mm512_mask_storeu_pd(p, static_cast<__mmask8>(lanesBelow(to) & ~lanesBelow(from)), v);
}
inline Vec broadcast(double x) { return _mm512_set1_pd(x); }
inline Vec minusProductPlus(Vec a, Vec b, Vec c) { return _mm512_fnmadd_pd(a, b, c); }
}  // namespace

#include "linalg/dense_front_kernels.inc"

}  // namespace aster::linalg::avx512
#endif
