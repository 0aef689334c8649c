#include "core/worker_pool.hpp"

#include <sched.h>
#include <signal.h>

#include <algorithm>
#include <condition_variable>
#include <cstdlib>
#include <deque>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

#include "core/machine_load.hpp"

namespace aster {

struct WorkerPool::Loop {
  const std::function<void(int)>* body = nullptr;
  int count = 0;
  int maxThreads = 0;
  int next = 0;     // first unclaimed item
  int running = 0;  // items claimed and not yet ended
  std::exception_ptr failure;
  bool done() const { return next == count && running == 0; }
  bool claimable() const { return next < count && (maxThreads <= 0 || running < maxThreads); }
};

// Everything below is guarded by `mutex`: the items are coarse (a chunk of cells, a subtree,
// a slice of a front), so one lock costs nothing next to them.
struct WorkerPool::State {
  std::mutex mutex;
  std::condition_variable changed;  // a loop opened, ended, or may take another thread
  std::deque<Loop*> open;           // loops with items left, oldest first
  std::vector<std::thread> workers;
  bool started = false;
  bool stopping = false;

  // With the lock held: claims an item of `only`, or of the oldest loop that has one.
  Loop* claim(Loop* only, int& item) {
    Loop* loop = nullptr;
    if (only) {
      if (only->claimable()) loop = only;
    } else {
      for (Loop* candidate : open)
        if (candidate->claimable()) {
          loop = candidate;
          break;
        }
    }
    if (!loop) return nullptr;
    item = loop->next++;
    ++loop->running;
    if (loop->next == loop->count) close(loop);
    return loop;
  }

  void close(Loop* loop) {
    const auto it = std::find(open.begin(), open.end(), loop);
    if (it != open.end()) open.erase(it);
  }

  // Runs a claimed item with the lock released; keeps its exception for the loop's owner.
  void run(std::unique_lock<std::mutex>& lock, Loop* loop, int item) {
    lock.unlock();
    std::exception_ptr failure;
    try {
      (*loop->body)(item);
    } catch (...) {
      failure = std::current_exception();
    }
    lock.lock();
    const bool wasFull = loop->maxThreads > 0 && loop->running >= loop->maxThreads;
    --loop->running;
    if (failure && !loop->failure) {
      loop->failure = failure;
      loop->next = loop->count;  // the items not yet claimed are skipped
      close(loop);
    }
    if (loop->done() || (wasFull && loop->next < loop->count)) changed.notify_all();
  }
};

namespace {

// OMP_NUM_THREADS: "4" or the first of a list "4,2"; 0 when not set.
int threadsAskedFor() {
  const char* value = std::getenv("OMP_NUM_THREADS");
  const int n = value ? std::atoi(value) : 0;
  return n >= 1 ? std::min(n, 64) : 0;
}

int threadsOfTheMachine() {
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) == 0) return std::clamp(CPU_COUNT(&set), 1, 64);
  return std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, 64);
}

}  // namespace

WorkerPool& WorkerPool::shared() {
  static const int asked = threadsAskedFor();
  static WorkerPool pool(asked ? asked : threadsOfTheMachine(), asked == 0);
  return pool;
}

WorkerPool::WorkerPool(int threads, bool yieldToOtherPrograms)
    : threads_(std::max(1, threads)),
      freeCores_(yieldToOtherPrograms && threads_ > 1 ? std::make_unique<FreeCoreWatch>(threads_) : nullptr),
      state_(new State) {}

int WorkerPool::threadsNow() { return freeCores_ ? freeCores_->threads() : threads_; }

WorkerPool::~WorkerPool() {
  {
    std::lock_guard<std::mutex> lock(state_->mutex);
    state_->stopping = true;
  }
  state_->changed.notify_all();
  for (std::thread& t : state_->workers) t.join();
  delete state_;
}

void WorkerPool::workerMain() {
  State& s = *state_;
  std::unique_lock<std::mutex> lock(s.mutex);
  while (!s.stopping) {
    int item = 0;
    if (Loop* loop = s.claim(nullptr, item))
      s.run(lock, loop, item);
    else
      s.changed.wait(lock);
  }
}

void WorkerPool::forEach(int count, const std::function<void(int)>& body, int maxThreads) {
  if (count <= 0) return;
  if (threads_ > 1 && count > 1) {
    const int now = threadsNow();
    if (maxThreads <= 0 || maxThreads > now) maxThreads = now;
  }
  if (threads_ == 1 || count == 1 || maxThreads == 1) {
    for (int i = 0; i < count; ++i) body(i);
    return;
  }
  State& s = *state_;
  std::unique_lock<std::mutex> lock(s.mutex);
  if (!s.started) {
    s.started = true;
    // Signals go to the program's own threads, never to a worker: blocked while the
    // workers start, they inherit the mask.
    sigset_t all, previous;
    sigfillset(&all);
    pthread_sigmask(SIG_BLOCK, &all, &previous);
    try {
      for (int t = 1; t < threads_; ++t) s.workers.emplace_back([this] { workerMain(); });
    } catch (const std::system_error&) {
      // Fewer workers than asked for (no room for another thread): the loops run on those there are.
    }
    pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  }
  Loop loop;
  loop.body = &body;
  loop.count = count;
  loop.maxThreads = maxThreads;
  s.open.push_back(&loop);
  s.changed.notify_all();
  for (;;) {
    int item = 0;
    if (s.claim(&loop, item)) {
      s.run(lock, &loop, item);
      continue;
    }
    if (loop.done()) break;
    if (Loop* other = s.claim(nullptr, item)) {  // help while the last items run elsewhere
      s.run(lock, other, item);
      continue;
    }
    s.changed.wait(lock);
  }
  s.close(&loop);
  lock.unlock();
  if (loop.failure) std::rethrow_exception(loop.failure);
}

}  // namespace aster
