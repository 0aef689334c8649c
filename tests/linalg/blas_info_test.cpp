#include "linalg/blas_info.hpp"

#include <gtest/gtest.h>

#include <dirent.h>
#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "linalg/linear_solver.hpp"

namespace aster::linalg {
namespace {

int processThreads() {
  int count = 0;
  if (DIR* tasks = opendir("/proc/self/task")) {
    while (const dirent* entry = readdir(tasks))
      if (entry->d_name[0] != '.') ++count;
    closedir(tasks);
  }
  return count;
}

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

// Every OPENBLAS_* / ASTER_BLAS_* variable of the process, "NAME=value" each: what a child
// process (gnuplot, gmsh) would inherit.
std::vector<std::string> blasVariables() {
  std::vector<std::string> found;
  for (char** v = environ; *v; ++v)
    if (!std::strncmp(*v, "OPENBLAS_", 9) || !std::strncmp(*v, "ASTER_BLAS", 10) || !std::strncmp(*v, "GLIBC_TUNABLES", 14))
      found.emplace_back(*v);
  return found;
}

void clearThreadVariables() {
  for (const char* v : {"OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS"}) unsetenv(v);
}

// Start-up: OpenBLAS on one thread, its workers stopped, the count it chose kept for large
// systems, and nothing written to the environment.
TEST(BlasInfo, StartOnOneThreadStopsTheWorkersWithoutTouchingTheEnvironment) {
  if (blasInUse().openblasConfig.empty()) GTEST_SKIP() << "not OpenBLAS";
  clearThreadVariables();
  const std::vector<std::string> before = blasVariables();
  const int chosen = startupBlasThreads();
  if (chosen < 2) GTEST_SKIP() << "OpenBLAS started on one thread (one core)";
  const int threadsBefore = processThreads();
  startBlasOnOneThread();
  EXPECT_EQ(blasInUse().threads, 1);
  EXPECT_EQ(processThreads(), threadsBefore - (chosen - 1)) << "OpenBLAS's workers still run";
  EXPECT_EQ(blasVariables(), before);
  chooseBlasThreads(kSmallSystem - 1);
  EXPECT_EQ(processThreads(), threadsBefore - (chosen - 1)) << "one thread asked: no worker";
  chooseBlasThreads(kSmallSystem);
  EXPECT_EQ(blasInUse().threads, chosen);
  EXPECT_EQ(processThreads(), threadsBefore) << "large systems: the workers again";
  chooseBlasThreads(kSmallSystem - 1);
  EXPECT_EQ(blasInUse().threads, 1);
  EXPECT_EQ(startupBlasThreads(), chosen);
}

TEST(BlasInfo, StartOnOneThreadLeavesTheUsersCount) {
  if (blasInUse().openblasConfig.empty()) GTEST_SKIP() << "not OpenBLAS";
  clearThreadVariables();
  const ScopedBlasThreads two(2);
  setenv("OPENBLAS_NUM_THREADS", "2", 1);
  startBlasOnOneThread();
  EXPECT_EQ(blasInUse().threads, 2);
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

// Only the generic Prescott kernels are replaced, and only by kernels this CPU runs.
TEST(BlasInfo, BetterKernelsReplaceOnlyTheGenericOnes) {
  EXPECT_EQ(betterBlasKernels("Haswell"), nullptr);
  EXPECT_EQ(betterBlasKernels("Cooperlake"), nullptr);
  EXPECT_EQ(betterBlasKernels(""), nullptr);
  const char* better = betterBlasKernels("Prescott");
  __builtin_cpu_init();
  if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma")) {
    EXPECT_EQ(better, nullptr);
  } else {
    ASSERT_NE(better, nullptr);  // a CPU with AVX2 + FMA (and an OS saving AVX: every Linux since 2.6.30)
    if (!__builtin_cpu_supports("avx512f")) {
      EXPECT_STREQ(better, "Haswell");
    }
  }
  EXPECT_EQ(betterBlasKernels("prescott") == nullptr, better == nullptr);
}

// C = A B for n x n column-major matrices, by the definition.
std::vector<double> product(const std::vector<double>& a, const std::vector<double>& b, int n) {
  std::vector<double> c(static_cast<size_t>(n) * n, 0.0);
  for (int j = 0; j < n; ++j)
    for (int k = 0; k < n; ++k)
      for (int i = 0; i < n; ++i) c[i + j * n] += a[i + k * n] * b[k + j * n];
  return c;
}

using Dgemm = void (*)(const char*, const char*, const int*, const int*, const int*, const double*, const double*,
                       const int*, const double*, const int*, const double*, double*, const int*);

// The kernels switched in the running process: OpenBLAS reports them, computes with them,
// and the environment is left as it was.
TEST(BlasInfo, SwitchKernelsInTheRunningProcess) {
  const std::string original = blasInUse().openblasCore;
  if (original.empty()) GTEST_SKIP() << "not OpenBLAS";
  if (!dlsym(RTLD_DEFAULT, "gotoblas_dynamic_init")) GTEST_SKIP() << "OpenBLAS built for one CPU";
  __builtin_cpu_init();
  const char* other = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") && original != "Haswell"
                          ? "Haswell"
                          : "Prescott";
  const std::vector<std::string> before = blasVariables();
  ASSERT_TRUE(switchBlasKernels(other));
  EXPECT_EQ(blasInUse().openblasCore, other);
  EXPECT_EQ(blasVariables(), before);
  const int n = 150;
  std::vector<double> a(static_cast<size_t>(n) * n), b(a.size()), c(a.size(), 0.0);
  for (size_t i = 0; i < a.size(); ++i) {
    a[i] = static_cast<double>((i * 7) % 13) - 6.0;
    b[i] = static_cast<double>((i * 5) % 11) - 5.0;
  }
  const auto dgemm = reinterpret_cast<Dgemm>(dlsym(RTLD_DEFAULT, "dgemm_"));
  ASSERT_NE(dgemm, nullptr);
  const double one = 1.0, zero = 0.0;
  dgemm("N", "N", &n, &n, &n, &one, a.data(), &n, b.data(), &n, &zero, c.data(), &n);
  EXPECT_EQ(c, product(a, b, n));  // small integers: exact in any order of summation
  EXPECT_TRUE(switchBlasKernels(original.c_str()));
  EXPECT_EQ(blasInUse().openblasCore, original);
}

// The user's OPENBLAS_CORETYPE is kept, whatever the kernels in use.
TEST(BlasInfo, SwitchKernelsKeepsTheUsersVariable) {
  const std::string original = blasInUse().openblasCore;
  if (original.empty() || !dlsym(RTLD_DEFAULT, "gotoblas_dynamic_init")) GTEST_SKIP() << "no OpenBLAS for several CPUs";
  setenv("OPENBLAS_CORETYPE", "Prescott", 1);
  selectBlasKernels();  // the user's choice: nothing done
  EXPECT_EQ(blasInUse().openblasCore, original);
  ASSERT_TRUE(switchBlasKernels(original.c_str()));
  EXPECT_STREQ(getenv("OPENBLAS_CORETYPE"), "Prescott");
  unsetenv("OPENBLAS_CORETYPE");
}

}  // namespace
}  // namespace aster::linalg
