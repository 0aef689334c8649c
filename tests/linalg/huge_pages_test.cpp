// Transparent huge pages asked for on large blocks: by adviseHugePages, and by the
// programs' malloc (src/huge_page_malloc.cpp, linked into this test as into aster-lite).
#include <sys/mman.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "linalg/factor_memory.hpp"

namespace aster::linalg {
namespace {

constexpr std::size_t kBlock = std::size_t{16} << 20;

// The kernel's mode: "always", "madvise" or "never".
std::string hugePageMode() {
  std::ifstream file("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string modes;
  std::getline(file, modes);
  const auto open = modes.find('['), close = modes.find(']');
  return open == std::string::npos || close == std::string::npos ? "" : modes.substr(open + 1, close - open - 1);
}

// AnonHugePages (kB) of the mappings that hold [data, data + bytes), from /proc/self/smaps.
long hugeKilobytesIn(const void* data, std::size_t bytes) {
  const auto begin = reinterpret_cast<std::uintptr_t>(data), end = begin + bytes;
  std::ifstream smaps("/proc/self/smaps");
  long total = 0;
  bool inside = false;
  for (std::string line; std::getline(smaps, line);) {
    std::uintptr_t from = 0, to = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> from >> dash >> to && dash == '-') {
      inside = from < end && to > begin;
    } else if (inside && line.rfind("AnonHugePages:", 0) == 0) {
      total += std::atol(line.c_str() + std::strlen("AnonHugePages:"));
    }
  }
  return total;
}

void touch(void* data, std::size_t bytes) { std::memset(data, 1, bytes); }

TEST(HugePages, AdvisedBlockGetsHugePages) {
  const std::string mode = hugePageMode();
  if (mode != "madvise" && mode != "always") GTEST_SKIP() << "transparent huge pages: " << mode;
  void* block = mmap(nullptr, kBlock, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  ASSERT_NE(block, MAP_FAILED);
  adviseHugePages(block, kBlock);
  touch(block, kBlock);
  EXPECT_GT(hugeKilobytesIn(block, kBlock), 0) << "no huge page in an advised, touched block of 16 MiB";
  munmap(block, kBlock);
}

// A block smaller than a huge page is left as it is (no advice that would split the heap).
TEST(HugePages, SmallBlockIsLeftAlone) {
  void* block = mmap(nullptr, std::size_t{1} << 20, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  ASSERT_NE(block, MAP_FAILED);
  adviseHugePages(block, std::size_t{1} << 20);
  touch(block, std::size_t{1} << 20);
  EXPECT_EQ(hugeKilobytesIn(block, std::size_t{1} << 20), 0);
  munmap(block, std::size_t{1} << 20);
}

// The programs' malloc: a large block from glibc gets huge pages in madvise mode too.
TEST(HugePages, ProgramMallocAdvisesLargeBlocks) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  GTEST_SKIP() << "the sanitizer's malloc";
#endif
  const std::string mode = hugePageMode();
  if (mode != "madvise" && mode != "always") GTEST_SKIP() << "transparent huge pages: " << mode;
  void* block = std::malloc(kBlock);
  ASSERT_NE(block, nullptr);
  touch(block, kBlock);
  EXPECT_GT(hugeKilobytesIn(block, kBlock), 0) << "no huge page in a touched malloc block of 16 MiB";
  std::free(block);
}

}  // namespace
}  // namespace aster::linalg
