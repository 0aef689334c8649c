// Large blocks of doubles kept from one factorization to the next.
//
// The multifrontal factorization allocates its update matrices afresh at every Newton
// iteration. Blocks of tens of MiB come from new mappings: above glibc's mmap threshold,
// and in the worker threads' arenas, whose heaps hold 64 MiB at most. Each new mapping is
// zeroed by the kernel page by page on first touch, about 2.5 s per GiB on the virtual
// machines this runs on: the SVK square at N = 512 paid 8 000 to 13 000 page faults per
// factorization for its top fronts' update matrices. A pool keeps such blocks when they are
// given back and hands them out again.
//
// take(n) returns the smallest free block of at least n entries and at most kSlack n (a
// small request does not hold a large block), or a new one. endRun() frees the blocks no
// take() asked for since the previous endRun(), so what stays between two runs is what the
// last run used, never more than it held at its peak plus the unused ends of the blocks.
// Blocks under kMinimumEntries are plain new[] / delete[]: glibc's heap keeps those.
// take() and giving back are thread-safe.
#pragma once
#include <cstddef>
#include <map>
#include <memory>
#include <mutex>

namespace aster::linalg {

class BlockPool {
 public:
  static constexpr std::size_t kMinimumEntries = std::size_t{4} << 20;  // 32 MiB of doubles
  static constexpr double kSlack = 1.5;

  // Gives a block back to its pool when dropped (to delete[] when it has none).
  struct Return {
    BlockPool* pool = nullptr;
    std::size_t capacity = 0;
    void operator()(double* block) const;
  };
  using Block = std::unique_ptr<double[], Return>;

  BlockPool() = default;
  ~BlockPool();
  BlockPool(const BlockPool&) = delete;
  BlockPool& operator=(const BlockPool&) = delete;

  // An uninitialized block of at least n doubles (n > 0). Throws std::bad_alloc.
  Block take(std::size_t n);
  void endRun();

  std::size_t freeBlocks() const;  // blocks kept, not handed out
  std::size_t freeEntries() const;

 private:
  struct Kept {
    double* block;
    bool takenThisRun;  // handed out since the last endRun()
  };
  void giveBack(double* block, std::size_t capacity);

  mutable std::mutex mutex_;
  std::multimap<std::size_t, Kept> free_;  // by capacity
};

}  // namespace aster::linalg
