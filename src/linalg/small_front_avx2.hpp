// The kernels of small_front.hpp built with -mavx2 -mfma (small_front_avx2.cpp).
#pragma once

namespace aster::linalg::avx2 {

// Rows of the packed copy of L21 the update reads: u rounded up to 4, and 8 more, zero.
inline int packedRows(int u) { return ((u + 3) / 4) * 4 + 8; }

int frontFactor(int width, int m, double* block);
void frontUpdate(int u, int width, const double* L21, int ld, double* U, double* packed);

}  // namespace aster::linalg::avx2
