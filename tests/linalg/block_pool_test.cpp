// The pool of large blocks the multifrontal factorization reuses across factorizations.
#include <gtest/gtest.h>

#include <vector>

#include "linalg/block_pool.hpp"

namespace aster::linalg {
namespace {

constexpr std::size_t kLarge = BlockPool::kMinimumEntries;

TEST(BlockPool, SmallBlocksAreNotKept) {
  BlockPool pool;
  BlockPool::Block block = pool.take(1000);
  EXPECT_EQ(block.get_deleter().pool, nullptr);
  block.reset();
  EXPECT_EQ(pool.freeBlocks(), 0u);
}

TEST(BlockPool, ALargeBlockGivenBackIsHandedOutAgain) {
  BlockPool pool;
  BlockPool::Block first = pool.take(kLarge + 10);
  double* address = first.get();
  first.reset();
  EXPECT_EQ(pool.freeBlocks(), 1u);
  EXPECT_EQ(pool.freeEntries(), kLarge + 10);
  BlockPool::Block again = pool.take(kLarge);  // smaller, within the slack
  EXPECT_EQ(again.get(), address);
  EXPECT_EQ(again.get_deleter().capacity, kLarge + 10);
  EXPECT_EQ(pool.freeBlocks(), 0u);
}

TEST(BlockPool, TheSmallestBlockThatFitsIsChosen) {
  BlockPool pool;
  std::vector<BlockPool::Block> blocks;
  for (std::size_t n : {kLarge + 300, kLarge + 100, kLarge + 200}) blocks.push_back(pool.take(n));
  double* middle = blocks[2].get();
  blocks.clear();
  BlockPool::Block chosen = pool.take(kLarge + 150);
  EXPECT_EQ(chosen.get(), middle);
  EXPECT_EQ(chosen.get_deleter().capacity, kLarge + 200);
}

TEST(BlockPool, ABlockFarLargerThanAskedIsNotHandedOut) {
  BlockPool pool;
  pool.take(2 * kLarge).reset();
  BlockPool::Block block = pool.take(kLarge);  // 2 > kSlack times larger: a new block
  EXPECT_EQ(block.get_deleter().capacity, kLarge);
  EXPECT_EQ(pool.freeBlocks(), 1u);
}

TEST(BlockPool, EndRunFreesTheBlocksTheRunDidNotUse) {
  BlockPool pool;
  pool.take(kLarge).reset();
  pool.take(2 * kLarge).reset();
  pool.endRun();  // both were used in this run: kept
  EXPECT_EQ(pool.freeBlocks(), 2u);
  pool.take(kLarge).reset();  // the next run uses one of them
  pool.endRun();
  EXPECT_EQ(pool.freeBlocks(), 1u);
  EXPECT_EQ(pool.freeEntries(), kLarge);
  pool.endRun();  // a run that used none
  EXPECT_EQ(pool.freeBlocks(), 0u);
}

TEST(BlockPool, ABlockStillHeldAtEndRunIsKeptWhenGivenBack) {
  BlockPool pool;
  BlockPool::Block held = pool.take(kLarge);
  pool.endRun();
  held.reset();
  pool.endRun();
  EXPECT_EQ(pool.freeBlocks(), 1u);
}

}  // namespace
}  // namespace aster::linalg
