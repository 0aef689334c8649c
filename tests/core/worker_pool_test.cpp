#include "core/worker_pool.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

namespace aster {
namespace {

TEST(WorkerPool, RunsEveryItemOnce) {
  WorkerPool pool(3);
  std::vector<std::atomic<int>> runs(1000);
  pool.forEach(1000, [&](int i) { ++runs[i]; });
  for (const auto& r : runs) EXPECT_EQ(r.load(), 1);
  pool.forEach(0, [&](int) { FAIL(); });
}

// Loops inside items (the factorization's subtrees): every item of every level runs once.
TEST(WorkerPool, NestedLoopsComplete) {
  WorkerPool pool(2);
  std::atomic<int> leaves{0};
  pool.forEach(4, [&](int) {
    pool.forEach(5, [&](int) { pool.forEach(6, [&](int) { ++leaves; }); });
  });
  EXPECT_EQ(leaves.load(), 4 * 5 * 6);
}

// Items are claimed as threads come free: while one thread is held in an item, the
// calling thread runs all the others (a fixed split would leave it waiting).
TEST(WorkerPool, AFreeThreadTakesTheItemsOfAHeldOne) {
  WorkerPool pool(2);
  const std::thread::id caller = std::this_thread::get_id();
  constexpr int kItems = 50;
  std::atomic<int> byCaller{0};
  std::atomic<bool> heldUntilTheOthersRan{false};
  pool.forEach(kItems, [&](int) {
    if (std::this_thread::get_id() == caller) {
      ++byCaller;
      return;
    }
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (byCaller.load() < kItems - 1 && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    heldUntilTheOthersRan = byCaller.load() == kItems - 1;
  });
  // Either the worker took one item and was held until the caller ran the 49 others, or
  // it never woke in time and the caller ran all 50.
  EXPECT_TRUE(heldUntilTheOthersRan.load() || byCaller.load() == kItems);
}

TEST(WorkerPool, RespectsTheThreadLimitOfALoop) {
  WorkerPool pool(4);
  std::atomic<int> inside{0}, most{0};
  pool.forEach(
      64,
      [&](int) {
        const int now = ++inside;
        int seen = most.load();
        while (now > seen && !most.compare_exchange_weak(seen, now)) {
        }
        std::this_thread::sleep_for(std::chrono::microseconds(200));
        --inside;
      },
      2);
  EXPECT_LE(most.load(), 2);
  EXPECT_GE(most.load(), 1);
}

TEST(WorkerPool, RethrowsTheFirstExceptionAndSkipsTheRest) {
  WorkerPool pool(2);
  std::atomic<int> ran{0};
  EXPECT_THROW(pool.forEach(10000,
                            [&](int i) {
                              ++ran;
                              if (i == 3) throw std::runtime_error("item 3");
                              std::this_thread::sleep_for(std::chrono::microseconds(50));
                            }),
               std::runtime_error);
  EXPECT_LT(ran.load(), 10000);
  // The pool is usable afterwards.
  std::atomic<int> after{0};
  pool.forEach(100, [&](int) { ++after; });
  EXPECT_EQ(after.load(), 100);
}

double processCpuSeconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// Idle workers sleep: after a loop, the process takes (almost) no processor time while
// the caller sleeps, where spinning workers would take all of theirs.
TEST(WorkerPool, IdleWorkersDoNotSpin) {
  WorkerPool pool(3);
  std::atomic<long> sum{0};
  pool.forEach(100, [&](int i) { sum += i; });
  const double before = processCpuSeconds();
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_LT(processCpuSeconds() - before, 0.05);  // spinning: about 0.6 s for two workers
  EXPECT_EQ(sum.load(), 4950);
}

// A pool with a fixed count (OMP_NUM_THREADS) does not yield: every thread, whatever else runs.
TEST(WorkerPool, AFixedCountIsKept) {
  WorkerPool pool(3);
  EXPECT_EQ(pool.threadsNow(), 3);
  WorkerPool yielding(3, true);
  EXPECT_GE(yielding.threadsNow(), 1);
  EXPECT_LE(yielding.threadsNow(), 3);
}

TEST(WorkerPool, OneThreadRunsInOrderOnTheCaller) {
  WorkerPool pool(1);
  std::vector<int> order;
  pool.forEach(5, [&](int i) { order.push_back(i); });
  EXPECT_EQ(order, (std::vector<int>{0, 1, 2, 3, 4}));
}

}  // namespace
}  // namespace aster
