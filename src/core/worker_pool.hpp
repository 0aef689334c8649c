// The threads of the program's parallel loops: the calling thread and a few workers.
//
// A loop is a count of independent items that threads claim one at a time; nothing is
// assigned in advance, so a thread that gets less of the machine (another program holding
// a core) claims fewer items and the loop ends about when the work is done, not when the
// slowest thread finishes a fixed share. A thread with nothing to claim sleeps on a
// condition variable instead of spinning: on a busy machine a spinning thread takes time
// from the one doing the work.
//
// Loops nest: an item may run a loop of its own (the factorization's subtrees and their
// fronts' dense kernels). A thread waiting for the items others are still running of its
// loop meanwhile runs unclaimed items of any loop (work stealing from the oldest loop first,
// whose items are the largest), so no thread sleeps while an item is left anywhere.
//
// The count of threads is fixed at the first use: OMP_NUM_THREADS when set (so the usual
// `OMP_NUM_THREADS=1` still means one thread), else the cores this process may run on.
// In the second case the pool yields to other programs: a loop runs on one thread per core
// they leave free (core/machine_load), since a thread sharing its core with another
// program gets a part of it only, and on a machine that shares its cores between sessions
// rather than threads (Linux's autogroup) two threads then get no more than one would.
#pragma once
#include <functional>
#include <memory>

namespace aster {

class FreeCoreWatch;

class WorkerPool {
 public:
  // The program's pool (workers started at the first loop that can use them).
  static WorkerPool& shared();

  explicit WorkerPool(int threads, bool yieldToOtherPrograms = false);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  // Threads a loop may run on, the calling thread included.
  int threads() const { return threads_; }

  // Threads a loop opened now runs on: threads(), or fewer while other programs hold cores.
  int threadsNow();

  // Runs body(i) for every i in [0, count) on the calling thread and on at most
  // maxThreads - 1 others at once (maxThreads <= 0: threadsNow()), and returns when every
  // item has run. The first exception an item throws is rethrown here, after the items
  // already running have ended; the items not yet claimed are then skipped.
  void forEach(int count, const std::function<void(int)>& body, int maxThreads = 0);

 private:
  void workerMain();

  struct Loop;  // one forEach call's shared state
  struct State;
  int threads_;
  std::unique_ptr<FreeCoreWatch> freeCores_;  // when yielding to other programs
  State* state_;
};

}  // namespace aster
