// The kernels of small_front.hpp, built for AVX2 + FMA (small_front_avx2.cpp) and for
// AVX-512 (small_front_avx512.cpp) from one source (small_front_kernels.inc).
#pragma once

namespace aster::linalg {

// Rows of the packed copy of L21 the update reads: u rounded up to 8, and 8 more, zero.
inline int packedRows(int u) { return ((u + 7) / 8) * 8 + 8; }

namespace avx2 {
int frontFactor(int width, int m, double* block);
void frontUpdate(int u, int width, const double* L21, int ld, double* U, double* packed);
}  // namespace avx2

namespace avx512 {
int frontFactor(int width, int m, double* block);
void frontUpdate(int u, int width, const double* L21, int ld, double* U, double* packed);
}  // namespace avx512

}  // namespace aster::linalg
