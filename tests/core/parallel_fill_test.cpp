// parallelFill: every entry written once, whatever the size against its pieces.
#include <gtest/gtest.h>

#include <vector>

#include "core/parallel_fill.hpp"

namespace aster {
namespace {

TEST(ParallelFill, FillsEveryEntryAndNothingElse) {
  constexpr std::size_t kPiece = std::size_t{1} << 20;
  for (std::size_t n : {std::size_t{0}, std::size_t{7}, 2 * kPiece - 1, 2 * kPiece, 3 * kPiece + 5}) {
    std::vector<int> data(n + 2, 5);
    parallelFill(data.data() + 1, n, -1);
    EXPECT_EQ(data.front(), 5) << n;
    EXPECT_EQ(data.back(), 5) << n;
    std::size_t filled = 0;
    for (std::size_t i = 1; i <= n; ++i) filled += data[i] == -1;
    EXPECT_EQ(filled, n);
  }
}

TEST(ParallelFill, FillsDoubles) {
  std::vector<double> data(5 * (std::size_t{1} << 20) + 3, 1.0);
  parallelFill(data.data(), data.size(), 0.0);
  for (double v : data) ASSERT_EQ(v, 0.0);
}

}  // namespace
}  // namespace aster
