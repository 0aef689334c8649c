// The sparse factorizations (UMFPACK, KLU, CHOLMOD, Eigen's LU) allocate their
// workspace afresh at every Newton iteration and free it afterwards: megabytes
// for a few thousand unknowns. glibc gives blocks above its mmap threshold back
// to the kernel at once, so every factorization paid page faults and zeroing on
// a fresh mapping: three quarters of the linear-solver time of the SSNP150
// studies (16 ms a factorization of 8 Mflop, 5 ms after this).
#pragma once

namespace aster::linalg {

// Keeps freed workspaces up to 64 MiB in the heap for the next factorization
// (and up to 256 MiB of free heap top); larger blocks are still mapped and
// returned one by one, so peak memory of large problems is unchanged.
// Called once, first thing in main().
void keepFactorWorkspaces();

// Memory touched for the first time costs a page fault per 4 KiB page: about 10 us on the
// virtual machines this runs on (2.8 s per GiB), 157 000 faults in the SVK square benchmark
// at N = 256. glibc's allocator asks for transparent huge pages (2 MiB, one fault each) when
// the tunable glibc.malloc.hugetlb=1 is set, which glibc reads only when a program starts:
// when the kernel grants huge pages on request (transparent_hugepage/enabled = madvise) and
// GLIBC_TUNABLES does not mention the tunable, this adds it and re-executes the program
// with the same arguments (SVK square N = 256: 15.1 -> 13.3 s, 18 600 faults). Returns
// when nothing is to be done, or when exec failed. ASTER_BLAS_SELECTED in the environment
// (tools/valgrind) keeps the process as it is.
void selectHugePages(char** argv);

}  // namespace aster::linalg
