// How much of the machine other programs are using, for work that only pays on free cores.
//
// The kernel counts, per CPU, the time spent running tasks (/proc/stat); the process
// counts its own CPU time. Between two samples, the CPU time the CPUs this process may run
// on spent running, minus what this process spent, is what the other programs took there,
// in cores once divided by the wall time. In a container whose /proc/stat is the host's and
// whose share is a quota rather than a set of CPUs, the answer errs towards "busy", which
// costs at most what the free cores would have given.
#pragma once
#include <atomic>
#include <mutex>
#include <string>

namespace aster {

struct CpuSample {
  double machineBusySeconds = -1;  // user, nice, system, irq, softirq of the CPUs counted; -1: unknown
  double ownSeconds = 0;           // this process's CPU time, all its threads
  double wallSeconds = 0;          // a monotonic clock
};

// One line of /proc/stat: the whole machine's ("cpu ", cpu = -1) or one CPU's ("cpu3 ",
// cpu = 3), with its busy time in clock ticks. False for any other line.
struct CpuLine {
  int cpu = -1;
  double busyTicks = 0;
};
bool parseCpuLine(const std::string& procStatLine, CpuLine& parsed);

// The CPUs this process may run on (its affinity), or the whole machine when that is not known.
CpuSample sampleCpu();

// The cores other programs used on average between the two samples; -1 when that cannot be
// told (no /proc/stat, or less than minimumWallSeconds between them: the kernel counts in
// ticks of 10 ms).
double coresUsedByOthers(const CpuSample& from, const CpuSample& to, double minimumWallSeconds = 0.05);

// A sample taken when the program started (the library's static initialization).
const CpuSample& programStartSample();

// The tasks of the machine runnable at this instant, the caller included: procs_running
// of /proc/stat (its text given), -1 when it has no such line.
int runnableTasks(const std::string& procStat);
int runnableTasksNow();

// Threads worth running on `threads` cores of which other programs use `others` (-1:
// unknown): one per core they leave, rounded, and at least one. A thread that shares a core
// with another program gets a part of it only, and the work it holds up waits for it.
int threadsOnFreeCores(int threads, double others);

// threadsOnFreeCores, kept up to date: measured over windows of `window` seconds (the
// first, from `start`, half as long), the last answer in between; before the first window
// ends, a guess from the tasks runnable when first asked (a program that keeps a core busy
// is always runnable; on an idle machine the caller is alone 99 times in 100). Any thread
// may ask; asking costs a clock read except once per window.
class FreeCoreWatch {
 public:
  explicit FreeCoreWatch(int threads, double windowSeconds = 0.2, const CpuSample& start = programStartSample());
  int threads();

 private:
  const int threads_;
  const double window_;
  std::atomic<int> answer_;
  std::atomic<double> nextCheck_;  // wall seconds
  std::mutex sampling_;  // guards what follows
  CpuSample last_;
  bool guessed_ = false;
};

}  // namespace aster
