// How much of the machine other programs are using, for work that only pays on an idle
// core.
//
// The kernel counts, per CPU, the time spent running tasks (/proc/stat); the process
// counts its own CPU time. Between two samples, the CPU time the machine spent running
// minus what this process spent is what the other programs took, in cores once divided by
// the wall time. On a machine whose cores all serve this process that tells whether
// another program holds one; in a container the count is the host's, and the answer errs
// towards "busy", which only costs what the idle-core work would have saved.
#pragma once
#include <string>

namespace aster {

struct CpuSample {
  double machineBusySeconds = -1;  // user, nice, system, irq, softirq of every CPU; -1: unknown
  double ownSeconds = 0;           // this process's CPU time, all its threads
  double wallSeconds = 0;          // a monotonic clock
};

// The busy time of the "cpu" line of /proc/stat, in clock ticks; -1 when the line has no
// such fields.
double busyTicks(const std::string& procStatCpuLine);

CpuSample sampleCpu();

// The cores other programs used on average between the two samples; -1 when that cannot be
// told (no /proc/stat, or less than minimumWallSeconds between them: the kernel counts in
// ticks of 10 ms).
double coresUsedByOthers(const CpuSample& from, const CpuSample& to, double minimumWallSeconds = 0.05);

// A sample taken when the program started (the library's static initialization).
const CpuSample& programStartSample();

}  // namespace aster
