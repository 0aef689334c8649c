// Fills a large array in pieces the worker pool's threads share. Memory written for the
// first time is zeroed by the kernel page by page, about 2 s per GiB on the virtual
// machines this runs on: filled on one thread, the assembly pattern of the SVK square at
// N = 512 (0.9 GB of positions, row indices and values) kept one core zeroing pages for
// about 2 s while the other waited.
#pragma once
#include <algorithm>
#include <cstddef>

#include "core/worker_pool.hpp"

namespace aster {

template <class T>
void parallelFill(T* data, std::size_t n, const T& value) {
  constexpr std::size_t kPiece = std::size_t{1} << 20;  // entries per item of the loop
  WorkerPool& pool = WorkerPool::shared();
  if (n < 2 * kPiece || pool.threads() < 2) {
    std::fill_n(data, n, value);
    return;
  }
  const int pieces = static_cast<int>((n + kPiece - 1) / kPiece);
  pool.forEach(pieces, [&](int p) {
    const std::size_t first = static_cast<std::size_t>(p) * kPiece;
    std::fill(data + first, data + std::min(n, first + kPiece), value);
  });
}

}  // namespace aster
