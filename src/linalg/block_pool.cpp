#include "linalg/block_pool.hpp"

namespace aster::linalg {

void BlockPool::Return::operator()(double* block) const {
  if (pool)
    pool->giveBack(block, capacity);
  else
    delete[] block;
}

BlockPool::~BlockPool() {
  for (auto& [capacity, kept] : free_) delete[] kept.block;
}

BlockPool::Block BlockPool::take(std::size_t n) {
  if (n < kMinimumEntries) return Block(new double[n], Return{});
  {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = free_.lower_bound(n);
    if (it != free_.end() && static_cast<double>(it->first) <= kSlack * static_cast<double>(n)) {
      Block block(it->second.block, Return{this, it->first});
      free_.erase(it);
      return block;
    }
  }
  return Block(new double[n], Return{this, n});
}

// A block given back counts as taken in this run: it was in use during it.
void BlockPool::giveBack(double* block, std::size_t capacity) {
  std::lock_guard<std::mutex> lock(mutex_);
  free_.emplace(capacity, Kept{block, true});
}

void BlockPool::endRun() {
  std::lock_guard<std::mutex> lock(mutex_);
  for (auto it = free_.begin(); it != free_.end();) {
    if (it->second.takenThisRun) {
      it->second.takenThisRun = false;
      ++it;
    } else {
      delete[] it->second.block;
      it = free_.erase(it);
    }
  }
}

std::size_t BlockPool::freeBlocks() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return free_.size();
}

std::size_t BlockPool::freeEntries() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::size_t total = 0;
  for (const auto& [capacity, kept] : free_) total += capacity;
  return total;
}

}  // namespace aster::linalg
