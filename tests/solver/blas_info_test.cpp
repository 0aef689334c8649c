#include "solver/blas_info.hpp"

#include <gtest/gtest.h>

#include "solver/linear_solver.hpp"

namespace aster::solver {
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

}  // namespace
}  // namespace aster::solver
