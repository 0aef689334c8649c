#include "core/machine_load.hpp"

#include <sched.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace aster {

bool parseCpuLine(const std::string& line, CpuLine& parsed) {
  if (line.compare(0, 3, "cpu") != 0 || line.size() < 4) return false;
  const char* fields = line.c_str() + 3;
  int cpu = -1;
  if (*fields != ' ') {  // "cpu3 ..."
    char* end = nullptr;
    const long n = std::strtol(fields, &end, 10);
    if (end == fields || *end != ' ' || n < 0 || n > 1 << 20) return false;
    cpu = static_cast<int>(n);
    fields = end;
  }
  unsigned long long user = 0, nice = 0, system = 0, idle = 0, iowait = 0, irq = 0, softirq = 0;
  if (std::sscanf(fields, "%llu %llu %llu %llu %llu %llu %llu", &user, &nice, &system, &idle, &iowait, &irq,
                  &softirq) != 7)
    return false;
  parsed.cpu = cpu;
  // Not idle nor iowait; steal is another virtual machine's, guest time is in user already.
  parsed.busyTicks = static_cast<double>(user + nice + system + irq + softirq);
  return true;
}

namespace {
double seconds(clockid_t clock) {
  timespec t{};
  clock_gettime(clock, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}
}  // namespace

CpuSample sampleCpu() {
  CpuSample s;
  s.wallSeconds = seconds(CLOCK_MONOTONIC);
  s.ownSeconds = seconds(CLOCK_PROCESS_CPUTIME_ID);
  const long ticksPerSecond = sysconf(_SC_CLK_TCK);
  cpu_set_t mine;
  const bool affinityKnown = sched_getaffinity(0, sizeof mine, &mine) == 0;
  std::FILE* f = std::fopen("/proc/stat", "r");
  if (!f) return s;
  double machine = -1, ours = 0;
  int oursCounted = 0;
  char line[512];
  while (std::fgets(line, sizeof line, f)) {
    CpuLine parsed;
    if (!parseCpuLine(line, parsed)) {
      if (machine >= 0) break;  // the cpu lines come first
      continue;
    }
    if (parsed.cpu < 0) {
      machine = parsed.busyTicks;
    } else if (affinityKnown && parsed.cpu < CPU_SETSIZE && CPU_ISSET(parsed.cpu, &mine)) {
      ours += parsed.busyTicks;
      ++oursCounted;
    }
  }
  std::fclose(f);
  const double ticks = oursCounted > 0 ? ours : machine;
  if (ticks >= 0 && ticksPerSecond > 0) s.machineBusySeconds = ticks / static_cast<double>(ticksPerSecond);
  return s;
}

double coresUsedByOthers(const CpuSample& from, const CpuSample& to, double minimumWallSeconds) {
  const double wall = to.wallSeconds - from.wallSeconds;
  if (from.machineBusySeconds < 0 || to.machineBusySeconds < 0 || wall < minimumWallSeconds) return -1;
  const double others = (to.machineBusySeconds - from.machineBusySeconds) - (to.ownSeconds - from.ownSeconds);
  return others > 0 ? others / wall : 0.0;
}

const CpuSample& programStartSample() {
  static const CpuSample start = sampleCpu();
  return start;
}

namespace {
// Taken at load time, before main(): the window starts with the program.
[[maybe_unused]] const CpuSample& startTaken = programStartSample();
}  // namespace

int runnableTasks(const std::string& procStat) {
  const std::string key = "\nprocs_running ";
  const size_t at = procStat.find(key);
  if (at == std::string::npos) return -1;
  char* end = nullptr;
  const char* digits = procStat.c_str() + at + key.size();
  const long n = std::strtol(digits, &end, 10);
  return end == digits || n < 0 || n > 1 << 20 ? -1 : static_cast<int>(n);
}

int runnableTasksNow() {
  std::FILE* f = std::fopen("/proc/stat", "r");
  if (!f) return -1;
  std::string text;
  char chunk[4096];
  for (size_t n; (n = std::fread(chunk, 1, sizeof chunk, f)) > 0;) text.append(chunk, n);
  std::fclose(f);
  return runnableTasks(text);
}

int threadsOnFreeCores(int threads, double others) {
  if (others < 0) return threads;
  const long taken = std::lround(others);
  return static_cast<int>(std::clamp<long>(threads - taken, 1, threads));
}

FreeCoreWatch::FreeCoreWatch(int threads, double windowSeconds, const CpuSample& start)
    : threads_(std::max(1, threads)),
      window_(windowSeconds),
      answer_(threads_),
      nextCheck_(0.0),  // the first ask guesses
      last_(start) {}

int FreeCoreWatch::threads() {
  if (threads_ == 1 || seconds(CLOCK_MONOTONIC) < nextCheck_.load(std::memory_order_relaxed))
    return answer_.load(std::memory_order_relaxed);
  std::unique_lock<std::mutex> lock(sampling_, std::try_to_lock);
  if (!lock.owns_lock()) return answer_.load(std::memory_order_relaxed);  // another thread is sampling
  if (!guessed_) {
    guessed_ = true;
    const int running = runnableTasksNow();
    if (running >= 1) answer_.store(threadsOnFreeCores(threads_, running - 1), std::memory_order_relaxed);
    nextCheck_.store(last_.wallSeconds + 0.5 * window_, std::memory_order_relaxed);
    return answer_.load(std::memory_order_relaxed);
  }
  const CpuSample now = sampleCpu();
  const double others = coresUsedByOthers(last_, now, 0.5 * window_);
  if (others >= 0) {
    answer_.store(threadsOnFreeCores(threads_, others), std::memory_order_relaxed);
    last_ = now;
  }
  nextCheck_.store(now.wallSeconds + window_, std::memory_order_relaxed);
  return answer_.load(std::memory_order_relaxed);
}

}  // namespace aster
