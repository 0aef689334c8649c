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

// Memory touched for the first time costs a page fault per 4 KiB page: about 10 us on the
// virtual machines this runs on (2.8 s per GiB). A transparent huge page (2 MiB) costs one.
// When the kernel grants them on request only (transparent_hugepage/enabled = madvise),
// this asks for them (madvise MADV_HUGEPAGE) on the whole 2 MiB pages inside the block,
// before it is touched; blocks smaller than 2 MiB are left alone. Nothing is lost when the
// kernel refuses. The programs' malloc calls it on every block (src/huge_page_malloc.cpp);
// the factor is advised here too, for builds without that malloc (sanitizers, tests).
void adviseHugePages(void* data, std::size_t bytes);

}  // namespace aster::linalg
