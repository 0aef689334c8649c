// The factor's memory, touched ahead on a thread of its own (src/linalg/warmed_block.hpp).
#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <thread>

#include "linalg/warmed_block.hpp"

namespace aster::linalg {
namespace {

constexpr std::size_t kMiB = std::size_t{1} << 20;

// Every 512th byte of the block is zero (the kernel's pages, and the warmer writes zeros).
bool zeroed(const double* block, std::size_t bytes) {
  const char* c = reinterpret_cast<const char*>(block);
  for (std::size_t at = 0; at < bytes; at += 512)
    if (c[at] != 0) return false;
  return c[bytes - 1] == 0;
}

void waitUntilTouched(const WarmedBlock& block, std::size_t bytes) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (block.touchedBytes() < bytes && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

TEST(WarmedBlock, WithoutWarmingTakeMapsAZeroedBlock) {
  WarmedBlock block(0);
  EXPECT_EQ(block.data(), nullptr);
  double* values = block.take(3 * kMiB + 8);
  ASSERT_NE(values, nullptr);
  EXPECT_EQ(block.data(), values);
  EXPECT_EQ(block.touchedBytes(), 0u);
  EXPECT_TRUE(zeroed(values, 3 * kMiB + 8));
  values[3 * kMiB / 8] = 1.5;  // writable to its last entry
  EXPECT_EQ(values[3 * kMiB / 8], 1.5);
}

TEST(WarmedBlock, TheThreadTouchesTheWholeEstimate) {
  WarmedBlock block(8 * kMiB + 100);  // rounded down to whole huge pages
  waitUntilTouched(block, 8 * kMiB);
  EXPECT_EQ(block.touchedBytes(), 8 * kMiB);
  double* values = block.take(8 * kMiB);
  EXPECT_TRUE(zeroed(values, 8 * kMiB));
}

TEST(WarmedBlock, ASmallerFactorKeepsTheStartOfTheBlock) {
  WarmedBlock block(8 * kMiB);
  waitUntilTouched(block, 8 * kMiB);
  double* values = block.take(5 * kMiB + 24);
  EXPECT_TRUE(zeroed(values, 5 * kMiB + 24));
  std::memset(values, 0x7f, 5 * kMiB + 24);
}

TEST(WarmedBlock, ALargerFactorGrowsTheBlock) {
  WarmedBlock block(4 * kMiB);
  double* values = block.take(20 * kMiB);  // whether or not the thread got far
  EXPECT_TRUE(zeroed(values, 20 * kMiB));
  std::memset(values, 0x7f, 20 * kMiB);
}

}  // namespace
}  // namespace aster::linalg
