// The sparse factorizations (UMFPACK, KLU, CHOLMOD, Eigen's LU) allocate their
// workspace afresh at every Newton iteration and free it afterwards: megabytes
// for a few thousand unknowns. glibc gives blocks above its mmap threshold back
// to the kernel at once, so every factorization paid page faults and zeroing on
// a fresh mapping: three quarters of the linear-solver time of the SSNP150
// studies (16 ms a factorization of 8 Mflop, 5 ms after this).
#pragma once

namespace aster::solver {

// Keeps freed workspaces up to 64 MiB in the heap for the next factorization
// (and up to 256 MiB of free heap top); larger blocks are still mapped and
// returned one by one, so peak memory of large problems is unchanged.
// Called once, first thing in main().
void keepFactorWorkspaces();

}  // namespace aster::solver
