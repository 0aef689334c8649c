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

// The programs' malloc: a large block from glibc gets huge pages in madvise mode too, where
// they pay (hugePagesPay: always, but while the process fits in the free memory a virtual
// machine's host still backs).
TEST(HugePages, ProgramMallocAdvisesLargeBlocksWhereTheyPay) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  GTEST_SKIP() << "the sanitizer's malloc";
#endif
  const std::string mode = hugePageMode();
  if (mode != "madvise") GTEST_SKIP() << "transparent huge pages: " << mode;
  const bool pays = hugePagesPay(kBlock);
  void* block = std::malloc(kBlock);
  ASSERT_NE(block, nullptr);
  touch(block, kBlock);
  if (pays)
    EXPECT_GT(hugeKilobytesIn(block, kBlock), 0) << "no huge page in a touched malloc block of 16 MiB";
  else
    EXPECT_EQ(hugeKilobytesIn(block, kBlock), 0) << "huge pages where 4 KiB pages are backed";
  std::free(block);
}

// The free memory in blocks below the reporting order, every zone: /proc/buddyinfo lists
// the free blocks of each order, 4 KiB pages times 2^order each.
TEST(HugePages, WarmFreeMemoryIsTheBlocksBelowTheReportingOrder) {
  const char* buddyinfo =
      "Node 0, zone      DMA      0      0      0      0      0      0      0      0      1      1      3 \n"
      "Node 0, zone    DMA32      0      4      2      2      1      2      0      3      3      1    753 \n"
      "Node 0, zone   Normal  15108   8206   3304   1184   1046    905    908   1121    827    653   1597 \n";
  const std::size_t page = 4096;
  const std::size_t dma32 = page * (0 + 4 * 2 + 2 * 4 + 2 * 8 + 1 * 16);
  const std::size_t normal = page * (15108 + 8206 * 2 + 3304 * 4 + 1184 * 8 + 1046 * 16);
  EXPECT_EQ(warmFreeBytes(buddyinfo, 5, page), dma32 + normal);
  EXPECT_EQ(warmFreeBytes(buddyinfo, 1, page), page * 15108);
  EXPECT_EQ(warmFreeBytes(buddyinfo, 0, page), 0u);
  EXPECT_EQ(warmFreeBytes("", 5, page), 0u);
  EXPECT_EQ(warmFreeBytes("Node 0, zone Normal 1 2\n", 5, page), page * (1 + 2 * 2));  // fewer orders listed
}

}  // namespace
}  // namespace aster::linalg
