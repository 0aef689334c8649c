// Memory for the factor, touched ahead of need while the ordering runs.
//
// On the virtual machines this runs on, the first touch of memory the host has not backed
// yet costs about 2 s per GiB (1.9-2.4 s measured, 0.07 s for memory the process had just
// given back), and a process starting after some idle time gets such memory: the first
// factorization of the SVK square at N = 256 took 0.95 s against 0.31 s for the others,
// most of the difference touching its 464 MB factor. The ordering before it (METIS) runs on one thread for 1 s
// at N = 256 and 4 to 5 s at N = 512, leaving a core idle. A WarmedBlock maps an estimate
// of the factor's size (transparent huge pages asked for where they pay) and touches it page by page on
// a thread of its own; once the symbolic analysis knows the size, take() stops the
// thread and fits the mapping to it, the pages touched kept (mremap), and the factor's
// values live there. Pages given back to the system and mapped again did not do: warmed,
// unmapped, then allocated by CHOLMOD, they saved 0.35 s of the 3 s at N = 512 (the
// guest's free page reporting to the host would explain it; not verified).
//
// With bytes = 0 (the caller's choice: CholmodSolver warms only a factor guessed at
// 64 MiB or more, with more than one thread and no other program taking a core) nothing
// is touched ahead: take() maps the block, and its
// pages are touched where they are first written.
#pragma once
#include <cstddef>

namespace aster::linalg {

class WarmedBlock {
 public:
  // Starts touching `bytes`, rounded down to 2 MiB, at most half of the memory free now.
  explicit WarmedBlock(std::size_t bytes);
  ~WarmedBlock();
  WarmedBlock(const WarmedBlock&) = delete;
  WarmedBlock& operator=(const WarmedBlock&) = delete;

  // Stops the touching and returns a block of `bytes` (> 0), the pages already touched
  // kept when it starts there. Once only. Throws std::bad_alloc when the system has no
  // memory for it.
  double* take(std::size_t bytes);
  double* data() const;  // what take() returned; null before
  std::size_t touchedBytes() const;  // touched ahead so far

 private:
  struct State;
  State* state_;
};

}  // namespace aster::linalg
