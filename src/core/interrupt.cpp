#include "core/interrupt.hpp"

#include <pthread.h>
#include <semaphore.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <thread>

namespace aster::interrupt {
namespace {

volatile std::sig_atomic_t pending = 0;

// The watchdog sleeps on this semaphore until the first Ctrl-C (sem_post is
// async-signal-safe, unlike condition variables).
sem_t wakeup;
std::atomic<bool> watchdogStarted{false};
std::atomic<bool> watched{false};
std::atomic<void (*)(void*)> handler{nullptr};
std::atomic<void*> handlerContext{nullptr};

extern "C" void onSigint(int) {
  const int saved = errno;
  pending = 1;
  std::signal(SIGINT, SIG_DFL);  // the next Ctrl-C is not polite any more
  if (watchdogStarted.load()) sem_post(&wakeup);
  errno = saved;
}

void* watchdog(void*) {
  while (sem_wait(&wakeup) != 0) {
  }
  using Clock = std::chrono::steady_clock;
  const auto grace = std::chrono::duration<double>(kWatchdogGrace);
  auto since = Clock::now();  // time spent watched since the request
  for (;;) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    if (!watched.load()) {
      since = Clock::now();  // a command: it stops at its own safe points
      continue;
    }
    if (Clock::now() - since < grace) continue;
    if (auto* h = handler.load()) {
      h(handlerContext.load());  // normally does not return
    } else {
      static const char message[] = "<F> <aster-lite> interrupted (SIGINT)\n";
      if (write(STDERR_FILENO, message, sizeof message - 1) < 0) {
      }
      _exit(130);
    }
    since = Clock::now();  // the handler declined: the run is already ending
  }
}

}  // namespace

void install() {
  // A run that inherited SIGINT ignored (started in the background of a script)
  // keeps ignoring it, as Unix programs do.
  struct sigaction previous{};
  sigaction(SIGINT, nullptr, &previous);
  if (previous.sa_handler == SIG_IGN) return;
  if (!watchdogStarted.load() && sem_init(&wakeup, 0, 0) == 0) {
    // The watchdog never takes SIGINT: the handler runs in the program's threads.
    sigset_t block, old;
    sigemptyset(&block);
    sigaddset(&block, SIGINT);
    pthread_sigmask(SIG_BLOCK, &block, &old);
    // pthread_create, not std::thread: std::thread puts the thread's state on the heap,
    // and the process forked to read a MED file would hold it without the thread
    // (a definite leak for valgrind).
    pthread_t thread;
    const bool started = pthread_create(&thread, nullptr, watchdog, nullptr) == 0;
    if (started) pthread_detach(thread);
    pthread_sigmask(SIG_SETMASK, &old, nullptr);
    watchdogStarted = started;
  }
  std::signal(SIGINT, onSigint);
}
bool requested() { return pending != 0; }
void clear() { pending = 0; }
void request() { pending = 1; }

Watch::Watch(bool on) : previous_(watched.exchange(on)) {}
Watch::~Watch() { watched = previous_; }

void setWatchdogHandler(void (*h)(void*), void* context) {
  handler = nullptr;
  handlerContext = context;
  handler = h;
}

}  // namespace aster::interrupt
