// glibc's allocator, asking for transparent huge pages on every large block it hands out:
// what the tunable glibc.malloc.hugetlb=1 does, but glibc reads tunables only from the
// environment when a program starts. Memory touched for the first time costs a page fault
// per 4 KiB page (about 10 us on the virtual machines this runs on); a huge page, one per
// 2 MiB (SVK square N = 256: 157 000 -> 18 600 faults). The program's malloc, calloc and
// realloc replace glibc's for every library (glibc's manual, "Replacing malloc"), pass the
// request on to glibc's own (__libc_malloc...) and advise the block where huge pages pay
// (linalg::adviseHugePagesWherePaying: not while the process's memory fits in the small
// free blocks a virtual machine's host still backs).
// Blocks are glibc's: glibc's free, memalign and malloc_usable_size work on them unchanged.
//
// Linked into the programs only (aster-lite, the bench), not into the libraries. Left out of
// sanitizer builds, whose runtimes replace malloc themselves; under valgrind, valgrind's
// allocator serves glibc's entries.
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>

#include "linalg/factor_memory.hpp"

#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)

namespace {

// Blocks below the mmap threshold come from the heap, which glibc extends with sbrk (and
// writes a chunk header into the new part, a 4 KiB page that keeps its 2 MiB range out of
// huge pages). The heap grows by 32 MiB at a time, and each growth is advised at once
// where huge pages pay.
[[maybe_unused]] const int heapGrowthSet = mallopt(M_TOP_PAD, 32 << 20);  // before main()

void adviseHeapGrowth(std::uintptr_t before) {
  const auto after = reinterpret_cast<std::uintptr_t>(sbrk(0));
  if (after > before && aster::linalg::hugePagesPay(after - before))
    madvise(reinterpret_cast<void*>(before), after - before, MADV_HUGEPAGE);
}

std::uintptr_t heapTop() { return reinterpret_cast<std::uintptr_t>(sbrk(0)); }

}  // namespace

extern "C" {
void* __libc_malloc(std::size_t bytes) noexcept;
void* __libc_calloc(std::size_t count, std::size_t size) noexcept;
void* __libc_realloc(void* block, std::size_t bytes) noexcept;

void* malloc(std::size_t bytes) noexcept {
  const std::uintptr_t top = heapTop();
  void* block = __libc_malloc(bytes);
  adviseHeapGrowth(top);
  if (block) aster::linalg::adviseHugePagesWherePaying(block, bytes);
  return block;
}

void* calloc(std::size_t count, std::size_t size) noexcept {
  const std::uintptr_t top = heapTop();
  void* block = __libc_calloc(count, size);
  adviseHeapGrowth(top);
  if (block) aster::linalg::adviseHugePagesWherePaying(block, count * size);  // no overflow: glibc checked it
  return block;
}

void* realloc(void* block, std::size_t bytes) noexcept {
  const std::uintptr_t top = heapTop();
  void* moved = __libc_realloc(block, bytes);
  adviseHeapGrowth(top);
  if (moved) aster::linalg::adviseHugePagesWherePaying(moved, bytes);
  return moved;
}
}

#endif
