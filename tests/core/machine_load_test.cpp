#include "core/machine_load.hpp"

#include <gtest/gtest.h>

namespace aster {
namespace {

TEST(MachineLoad, ReadsTheBusyTicksOfTheCpuLine) {
  // user nice system idle iowait irq softirq steal guest guest_nice
  EXPECT_EQ(busyTicks("cpu  4196333 0 672241 2500818 10802 0 4027 11492 0 0\n"), 4196333.0 + 672241 + 4027);
  EXPECT_EQ(busyTicks("cpu 1 2 3 4 5 6 7"), 1.0 + 2 + 3 + 6 + 7);
  EXPECT_EQ(busyTicks("cpu0 1 2 3 4 5 6 7"), -1);
  EXPECT_EQ(busyTicks("cpu 1 2 3"), -1);
  EXPECT_EQ(busyTicks(""), -1);
}

TEST(MachineLoad, OthersAreWhatTheMachineRanLessWhatTheProcessRan) {
  CpuSample from, to;
  from.machineBusySeconds = 100.0;
  from.ownSeconds = 2.0;
  from.wallSeconds = 10.0;
  to.machineBusySeconds = 103.0;  // 3 s of CPU time in 2 s
  to.ownSeconds = 3.0;            // 1 s of it this process's
  to.wallSeconds = 12.0;
  EXPECT_DOUBLE_EQ(coresUsedByOthers(from, to), 1.0);
  to.ownSeconds = 6.0;  // the ticks lag the process's clock: never below zero
  EXPECT_DOUBLE_EQ(coresUsedByOthers(from, to), 0.0);
  to.wallSeconds = 10.01;  // too short a window to tell
  EXPECT_EQ(coresUsedByOthers(from, to), -1);
  from.machineBusySeconds = -1;  // no /proc/stat
  EXPECT_EQ(coresUsedByOthers(from, to), -1);
}

TEST(MachineLoad, SamplesTheRunningSystem) {
  const CpuSample s = sampleCpu();
  if (s.machineBusySeconds < 0) GTEST_SKIP() << "no /proc/stat";
  EXPECT_GT(s.machineBusySeconds, 0.0);
  EXPECT_GE(s.ownSeconds, 0.0);
  EXPECT_GE(s.wallSeconds, programStartSample().wallSeconds);
}

}  // namespace
}  // namespace aster
