#include "core/machine_load.hpp"

#include <gtest/gtest.h>
#include <sched.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

namespace aster {
namespace {

TEST(MachineLoad, ReadsTheBusyTicksOfTheCpuLines) {
  // user nice system idle iowait irq softirq steal guest guest_nice
  CpuLine line;
  ASSERT_TRUE(parseCpuLine("cpu  4196333 0 672241 2500818 10802 0 4027 11492 0 0\n", line));
  EXPECT_EQ(line.cpu, -1);
  EXPECT_EQ(line.busyTicks, 4196333.0 + 672241 + 4027);
  ASSERT_TRUE(parseCpuLine("cpu 1 2 3 4 5 6 7", line));
  EXPECT_EQ(line.busyTicks, 1.0 + 2 + 3 + 6 + 7);
  ASSERT_TRUE(parseCpuLine("cpu12 1 2 3 4 5 6 7 8 9 10", line));
  EXPECT_EQ(line.cpu, 12);
  EXPECT_EQ(line.busyTicks, 1.0 + 2 + 3 + 6 + 7);
  EXPECT_FALSE(parseCpuLine("cpu 1 2 3", line));
  EXPECT_FALSE(parseCpuLine("cpux 1 2 3 4 5 6 7", line));
  EXPECT_FALSE(parseCpuLine("cpu3", line));
  EXPECT_FALSE(parseCpuLine("intr 1 2 3 4 5 6 7", line));
  EXPECT_FALSE(parseCpuLine("", line));
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

TEST(MachineLoad, OneThreadPerCoreTheOthersLeave) {
  EXPECT_EQ(threadsOnFreeCores(2, -1), 2);  // unknown: every core
  EXPECT_EQ(threadsOnFreeCores(2, 0.0), 2);
  EXPECT_EQ(threadsOnFreeCores(2, 0.4), 2);
  EXPECT_EQ(threadsOnFreeCores(2, 0.6), 1);  // a busy loop beside two threads of ours: 2/3 of a core
  EXPECT_EQ(threadsOnFreeCores(2, 1.0), 1);
  EXPECT_EQ(threadsOnFreeCores(2, 5.0), 1);  // never none
  EXPECT_EQ(threadsOnFreeCores(8, 1.0), 7);
  EXPECT_EQ(threadsOnFreeCores(8, 2.7), 5);
  EXPECT_EQ(threadsOnFreeCores(1, 0.0), 1);
}

TEST(MachineLoad, SamplesTheRunningSystem) {
  const CpuSample s = sampleCpu();
  if (s.machineBusySeconds < 0) GTEST_SKIP() << "no /proc/stat";
  EXPECT_GT(s.machineBusySeconds, 0.0);
  EXPECT_GE(s.ownSeconds, 0.0);
  EXPECT_GE(s.wallSeconds, programStartSample().wallSeconds);
}

TEST(MachineLoad, ReadsTheRunnableTasks) {
  EXPECT_EQ(runnableTasks("cpu  1 2 3 4 5 6 7\nctxt 5\nprocs_running 3\nprocs_blocked 0\n"), 3);
  EXPECT_EQ(runnableTasks("cpu  1 2 3 4 5 6 7\nprocs_blocked 0\n"), -1);
  EXPECT_EQ(runnableTasks("cpu  1 2 3 4 5 6 7\nprocs_running x\n"), -1);
  if (sampleCpu().machineBusySeconds >= 0) {
    EXPECT_GE(runnableTasksNow(), 1);  // this thread
  }
}

// A child process that spins on one of this process's cores is another program: the watch
// leaves it that core, from its first answer (the child is runnable) and after a window.
TEST(MachineLoad, TheWatchLeavesACoreToASpinningProcess) {
  cpu_set_t mine;
  ASSERT_EQ(sched_getaffinity(0, sizeof mine, &mine), 0);
  const int cores = CPU_COUNT(&mine);
  if (cores < 2) GTEST_SKIP() << "one core";
  if (sampleCpu().machineBusySeconds < 0) GTEST_SKIP() << "no /proc/stat";
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    volatile unsigned long spins = 0;
    while (std::chrono::steady_clock::now() < end) ++spins;
    _exit(0);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  FreeCoreWatch watch(cores, 0.2, sampleCpu());
  const int guessed = watch.threads();
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  const int measured = watch.threads();
  kill(child, SIGKILL);
  waitpid(child, nullptr, 0);
  EXPECT_GE(guessed, 1);
  EXPECT_LE(guessed, cores - 1);
  EXPECT_GE(measured, 1);
  EXPECT_LE(measured, cores - 1);
}

}  // namespace
}  // namespace aster
