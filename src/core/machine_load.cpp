#include "core/machine_load.hpp"

#include <time.h>
#include <unistd.h>

#include <cstdio>

namespace aster {

double busyTicks(const std::string& line) {
  unsigned long long user = 0, nice = 0, system = 0, idle = 0, iowait = 0, irq = 0, softirq = 0;
  if (line.compare(0, 4, "cpu ") != 0) return -1;  // the whole machine's line, not one CPU's
  if (std::sscanf(line.c_str() + 4, "%llu %llu %llu %llu %llu %llu %llu", &user, &nice, &system, &idle, &iowait, &irq,
                  &softirq) != 7)
    return -1;
  // Not idle nor iowait; steal is another virtual machine's, guest time is in user already.
  return static_cast<double>(user + nice + system + irq + softirq);
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
  if (std::FILE* f = std::fopen("/proc/stat", "r")) {
    char line[256] = {};
    if (std::fgets(line, sizeof line, f) && ticksPerSecond > 0) {
      const double ticks = busyTicks(line);
      if (ticks >= 0) s.machineBusySeconds = ticks / static_cast<double>(ticksPerSecond);
    }
    std::fclose(f);
  }
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

}  // namespace aster
