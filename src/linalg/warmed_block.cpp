#include "linalg/warmed_block.hpp"

#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <new>
#include <system_error>
#include <thread>

#include "linalg/factor_memory.hpp"

namespace aster::linalg {

namespace {
constexpr std::size_t kHugePage = std::size_t{2} << 20;
constexpr std::size_t kPage = 4096;
}  // namespace

struct WarmedBlock::State {
  void* block = nullptr;  // the mapping (null: none yet)
  std::size_t bytes = 0;  // its length
  std::atomic<bool> stop{false};
  std::atomic<std::size_t> touched{0};
  std::thread thread;
  bool taken = false;
};

WarmedBlock::WarmedBlock(std::size_t bytes) : state_(new State) {
  // An estimate far above the factor (a matrix with little fill) must not take the memory
  // other programs use: at most half of what is free now.
  const long freePages = sysconf(_SC_AVPHYS_PAGES), pageSize = sysconf(_SC_PAGESIZE);
  if (freePages > 0 && pageSize > 0)
    bytes = std::min(bytes, static_cast<std::size_t>(freePages) * static_cast<std::size_t>(pageSize) / 2);
  bytes = bytes / kHugePage * kHugePage;
  if (bytes == 0) return;
  void* block = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (block == MAP_FAILED) return;
  state_->block = block;
  state_->bytes = bytes;
  adviseHugePagesWherePaying(block, bytes);
  try {
    state_->thread = std::thread([s = state_] {
      volatile char* pages = static_cast<char*>(s->block);
      for (std::size_t at = 0; at < s->bytes && !s->stop.load(std::memory_order_relaxed); at += kPage) {
        pages[at] = 0;  // what the kernel wrote already: the block's contents stay zero
        s->touched.store(at + kPage, std::memory_order_relaxed);
      }
    });
  } catch (const std::system_error&) {  // no thread to spare: nothing touched ahead
  }
}

WarmedBlock::~WarmedBlock() {
  state_->stop = true;
  if (state_->thread.joinable()) state_->thread.join();
  if (state_->block) munmap(state_->block, state_->bytes);
  delete state_;
}

double* WarmedBlock::take(std::size_t bytes) {
  State& s = *state_;
  s.stop = true;
  if (s.thread.joinable()) s.thread.join();
  if (!s.block) {
    void* block = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (block == MAP_FAILED) throw std::bad_alloc();
    adviseHugePagesWherePaying(block, bytes);
    s.block = block;
  } else if (bytes != s.bytes) {
    void* block = mremap(s.block, s.bytes, bytes, MREMAP_MAYMOVE);
    if (block == MAP_FAILED) throw std::bad_alloc();
    if (bytes > s.bytes) adviseHugePagesWherePaying(block, bytes);
    s.block = block;
  }
  s.bytes = bytes;
  s.taken = true;
  return static_cast<double*>(s.block);
}

double* WarmedBlock::data() const { return state_->taken ? static_cast<double*>(state_->block) : nullptr; }

std::size_t WarmedBlock::touchedBytes() const { return state_->touched.load(); }

}  // namespace aster::linalg
