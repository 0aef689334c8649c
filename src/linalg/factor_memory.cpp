#include "linalg/factor_memory.hpp"

#include <fcntl.h>
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <cstring>

namespace aster::linalg {

void keepFactorWorkspaces() {
  // Setting them fixes both thresholds (glibc stops adjusting them by itself).
  mallopt(M_MMAP_THRESHOLD, 64 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
}

std::size_t warmFreeBytes(const char* buddyinfo, int reportingOrder, std::size_t pageBytes) {
  std::size_t bytes = 0;
  for (const char* line = buddyinfo; line && *line;) {
    const char* next = std::strchr(line, '\n');
    const char* zone = std::strstr(line, "zone");
    if (zone && (!next || zone < next)) {
      const char* p = zone + 4;
      while (*p == ' ') ++p;
      while (*p && *p != ' ' && *p != '\n') ++p;  // the zone's name
      for (int order = 0; order < reportingOrder; ++order) {
        char* end = nullptr;
        const unsigned long long count = std::strtoull(p, &end, 10);
        if (end == p || (next && end > next)) break;
        bytes += static_cast<std::size_t>(count) * (pageBytes << order);
        p = end;
      }
    }
    line = next ? next + 1 : nullptr;
  }
  return bytes;
}

namespace {
// A small file's text into `text` (NUL-terminated), by system calls only: this runs inside
// malloc. False when it cannot be read.
bool readSmallFile(const char* path, char* text, std::size_t size) {
  const int fd = open(path, O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  std::size_t used = 0;
  for (ssize_t n; used + 1 < size && (n = read(fd, text + used, size - 1 - used)) > 0;) used += static_cast<std::size_t>(n);
  close(fd);
  text[used] = '\0';
  return used > 0;
}

std::size_t pageBytes() {
  const long page = sysconf(_SC_PAGESIZE);
  return static_cast<std::size_t>(page > 0 ? page : 4096);
}

// The process's resident memory (/proc/self/statm: "size resident ...", in pages), 0 when unknown.
std::size_t residentBytes() {
  char text[128];
  if (!readSmallFile("/proc/self/statm", text, sizeof text)) return 0;
  const char* resident = std::strchr(text, ' ');
  return resident ? static_cast<std::size_t>(std::strtoull(resident, nullptr, 10)) * pageBytes() : 0;
}

// warmFreeBytes of this machine now; 0 without free page reporting.
std::size_t warmFreeBytesNow() {
  char order[32], buddyinfo[4096];
  if (!readSmallFile("/sys/module/page_reporting/parameters/page_reporting_order", order, sizeof order)) return 0;
  if (!readSmallFile("/proc/buddyinfo", buddyinfo, sizeof buddyinfo)) return 0;
  return warmFreeBytes(buddyinfo, std::atoi(order), pageBytes());
}

std::atomic<bool> footprintReached{false};
}  // namespace

bool hugePagesPay(std::size_t bytes) {
  if (footprintReached.load(std::memory_order_relaxed)) return true;
  static const std::size_t warm = warmFreeBytesNow();  // at the first large block
  if (warm == 0 || residentBytes() + bytes >= warm) {
    footprintReached.store(true, std::memory_order_relaxed);
    return true;
  }
  return false;
}

void adviseHugePages(void* data, std::size_t bytes) {
  constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
  const auto start = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t begin = (start + kHugePage - 1) & ~(kHugePage - 1);
  const std::uintptr_t end = (start + bytes) & ~(kHugePage - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
}

void adviseHugePagesWherePaying(void* data, std::size_t bytes) {
  if (bytes >= (std::size_t{2} << 20) && hugePagesPay(bytes)) adviseHugePages(data, bytes);
}

}  // namespace aster::linalg
