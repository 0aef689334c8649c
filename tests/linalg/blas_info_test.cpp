#include "linalg/blas_info.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

#include "linalg/linear_solver.hpp"

namespace aster::linalg {
namespace {

TEST(BlasInfo, ReportsTheLibraryCholmodLoaded) {
  // Linking CHOLMOD loads libblas.so.3, whichever implementation the system selected.
  auto solver = makeLinearSolver("CHOLMOD");
  const BlasInfo info = blasInUse();
  EXPECT_FALSE(info.library.empty());
  EXPECT_NE(info.library.find("blas"), std::string::npos) << info.library;
  RecordProperty("blas", info.library);
  if (info.library.find("openblas") != std::string::npos) {
    EXPECT_FALSE(info.openblasConfig.empty());
  }
}

// OpenBLAS's thread count inside the scope, the previous one after; nested scopes unwind.
TEST(BlasInfo, ScopedBlasThreadsRestoresTheCount) {
  const int before = blasInUse().threads;
  {
    ScopedBlasThreads one(1);
    EXPECT_EQ(blasInUse().threads, 1);
    {
      ScopedBlasThreads two(2);
      if (blasInUse().openblasConfig.empty()) GTEST_SKIP() << "not OpenBLAS";
      EXPECT_EQ(blasInUse().threads, 2);
    }
    EXPECT_EQ(blasInUse().threads, 1);
  }
  EXPECT_EQ(blasInUse().threads, before);
}

void clearThreadVariables() {
  for (const char* v : {"OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "ASTER_BLAS_THREADS"}) unsetenv(v);
}

// Before re-executing: one thread for the new process, the count OpenBLAS chose kept aside.
TEST(BlasInfo, StartOnOneThreadSetsTheNewProcessVariables) {
  if (blasInUse().openblasConfig.empty()) GTEST_SKIP() << "not OpenBLAS";
  clearThreadVariables();
  const int chosen = blasInUse().threads;
  startBlasOnOneThread();
  ASSERT_NE(getenv("OPENBLAS_NUM_THREADS"), nullptr);
  EXPECT_STREQ(getenv("OPENBLAS_NUM_THREADS"), "1");
  ASSERT_NE(getenv("ASTER_BLAS_THREADS"), nullptr);
  EXPECT_EQ(std::atoi(getenv("ASTER_BLAS_THREADS")), chosen);
  clearThreadVariables();
}

TEST(BlasInfo, StartOnOneThreadLeavesTheUsersCount) {
  clearThreadVariables();
  setenv("OPENBLAS_NUM_THREADS", "3", 1);
  startBlasOnOneThread();
  EXPECT_STREQ(getenv("OPENBLAS_NUM_THREADS"), "3");
  EXPECT_EQ(getenv("ASTER_BLAS_THREADS"), nullptr);
  clearThreadVariables();
}

// The re-executed process: OpenBLAS on one thread, large systems get the count chosen before.
TEST(BlasInfo, LargeSystemsGetTheCountChosenBeforeTheReexecution) {
  if (blasInUse().openblasConfig.empty()) GTEST_SKIP() << "not OpenBLAS";
  clearThreadVariables();
  setenv("OPENBLAS_NUM_THREADS", "1", 1);
  setenv("ASTER_BLAS_THREADS", "3", 1);  // not the count this process started with
  chooseBlasThreads(kSmallSystem);
  EXPECT_EQ(blasInUse().threads, 3);
  chooseBlasThreads(kSmallSystem - 1);
  EXPECT_EQ(blasInUse().threads, 1);
  clearThreadVariables();
}

TEST(BlasInfo, ChooseLeavesTheUsersCount) {
  if (blasInUse().openblasConfig.empty()) GTEST_SKIP() << "not OpenBLAS";
  clearThreadVariables();
  ScopedBlasThreads two(2);
  setenv("OMP_NUM_THREADS", "2", 1);
  chooseBlasThreads(1);
  EXPECT_EQ(blasInUse().threads, 2);
  clearThreadVariables();
}

}  // namespace
}  // namespace aster::linalg
