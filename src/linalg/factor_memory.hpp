// The sparse factorizations (UMFPACK, KLU, CHOLMOD, Eigen's LU) allocate their
// workspace afresh at every Newton iteration and free it afterwards: megabytes
// for a few thousand unknowns. glibc gives blocks above its mmap threshold back
// to the kernel at once, so every factorization paid page faults and zeroing on
// a fresh mapping: three quarters of the linear-solver time of the SSNP150
// studies (16 ms a factorization of 8 Mflop, 5 ms after this).
#pragma once
#include <cstddef>

namespace aster::linalg {

// Keeps freed workspaces up to 64 MiB in the heap for the next factorization
// (and up to 256 MiB of free heap top); larger blocks are still mapped and
// returned one by one, so peak memory of large problems is unchanged.
// Called once, first thing in main().
void keepFactorWorkspaces();

// Memory touched for the first time costs a page fault per 4 KiB page; a transparent huge
// page (2 MiB) costs one. When the kernel grants them on request only
// (transparent_hugepage/enabled = madvise), this asks for them (madvise MADV_HUGEPAGE) on
// the whole 2 MiB pages inside the block, before it is touched; blocks smaller than 2 MiB
// are left alone. Nothing is lost when the kernel refuses.
void adviseHugePages(void* data, std::size_t bytes);

// adviseHugePages when hugePagesPay(bytes). The programs' malloc calls it on every block
// (src/huge_page_malloc.cpp); the factor's storage calls it too, for builds without that
// malloc (sanitizers, tests).
void adviseHugePagesWherePaying(void* data, std::size_t bytes);

// Whether huge pages pay for a block of `bytes` about to be touched. Always, but on a
// virtual machine whose kernel reports free memory to the host (free page reporting, as on
// the machines this runs on): there a free block of the reporting order or above (128 KiB
// here) is given back to the host, which backs it afresh when it is touched again (about
// 6 ms per MiB), while the smaller free blocks, left by the programs that ran before, are
// still backed. 4 KiB pages come from those first; a huge page needs a whole free 2 MiB
// block. So huge pages are asked for once the process's resident memory with `bytes`
// reaches the free memory below the reporting order when the program asked for its first
// large block (/proc/buddyinfo), and from then on: fresh 4 KiB pages cost more than fresh huge pages.
// SVK square right after CalculiX's run, against huge pages everywhere: N = 64 0.22-0.25 s
// against 0.30-0.38 s, N = 128 (250 MiB; 257 MiB of such free blocks) 1.07-1.13 s against
// 1.64-1.78 s, N = 256 7.0-7.2 s against 7.6-7.9 s; N = 512 (4.4 GiB), one run after
// another, 33.5-35.3 s (once 42.5 s) against 34.0-35.6 s (with the first 512 MiB in 4 KiB
// pages whatever the free blocks: 36-42 s).
bool hugePagesPay(std::size_t bytes);

// The free memory in blocks below `reportingOrder` (pages of `pageBytes`, 2^order of them
// per block) that /proc/buddyinfo's text lists, every zone.
std::size_t warmFreeBytes(const char* buddyinfo, int reportingOrder, std::size_t pageBytes);

}  // namespace aster::linalg
