// Which BLAS the process uses (CHOLMOD's supernodal factorization calls dgemm/dsyrk/dpotrf).
// aster-lite links OpenBLAS explicitly (cmake/Dependencies.cmake), so its dgemm_ comes
// before the libblas.so.3 that CHOLMOD names, whatever Debian's alternatives select;
// this reports the library actually loaded.
#pragma once
#include <string>

namespace aster::linalg {

struct BlasInfo {
  std::string library;  // resolved file providing dgemm_, empty if no BLAS is loaded
  std::string openblasConfig;  // openblas_get_config() when OpenBLAS is loaded, empty otherwise
  std::string openblasCore;    // openblas_get_corename(): the kernels OpenBLAS chose
  int threads = 1;             // openblas_get_num_threads(), 1 for another BLAS
};

BlasInfo blasInUse();

// OpenBLAS built for several CPUs (Debian's) picks its kernels from the CPU model; a model
// newer than the library (Debian 12's 0.3.21 on Sapphire/Emerald Rapids) falls back to the
// generic SSE3 "Prescott" kernels, 5x slower. When that happened, OPENBLAS_CORETYPE is unset
// and the CPU and the OS support AVX-512 (or AVX2), this sets OPENBLAS_CORETYPE to SkylakeX
// (or Haswell) and re-executes the program with the same arguments, since OpenBLAS reads the
// variable when it is loaded. Returns only when nothing is to be done or exec failed.
void selectBlasKernels(char** argv);

// One BLAS thread for factorizations of fewer than kSmallSystem unknowns, the
// BLAS's own count (all cores) for larger ones. The dense blocks of a small
// sparse factorization are tiny: a second thread costs more to wake and to spin
// than it computes (ssnp150a, 1705 unknowns: 0.57 s -> 0.51 s). Leaves the
// count alone when the user set OPENBLAS_NUM_THREADS or OMP_NUM_THREADS, or when
// the BLAS is not OpenBLAS.
inline constexpr int kSmallSystem = 10000;
void chooseBlasThreads(int unknowns);

// OpenBLAS creates its worker threads when it is loaded, and an idle worker spins
// (sched_yield) for a while before it sleeps: on two cores it slows whatever the
// program does first (loading libmedC in ssnp150a: 32 -> 19 ms). The default
// solver needs no BLAS thread (multifrontal_cholesky.cpp), so a process about to
// re-execute itself (selectBlasKernels, selectHugePages) calls this: the new
// process starts OpenBLAS on one thread (OPENBLAS_NUM_THREADS=1) and
// chooseBlasThreads still gives large systems the count OpenBLAS had chosen,
// creating the workers then. Nothing when the user chose the count.
void startBlasOnOneThread();

// The count OpenBLAS chose when the program was started (in the first process when
// startBlasOnOneThread re-executed it): all cores unless the user set it; 1 for another BLAS.
int startupBlasThreads();

// OpenBLAS (Debian 12's 0.3.21) maps a 128 MiB work buffer for each BLAS call in flight
// and for each of its threads, keeps it for the next calls, and retries forever when
// the mapping fails because the address space is limited (ulimit -v, prlimit --as;
// OpenBLAS issue 5289): the program would hang. Under such a limit,
// reserveBlasBuffer maps the first buffer at start-up, while there is room, and
// returns an error message when there is none ("" when done or nothing to do);
// blasCallersThatFit(n) is how many of n concurrent BLAS callers (or OpenBLAS
// threads) the address space left can take, at least 1 (n without a limit).
std::string reserveBlasBuffer();
int blasCallersThatFit(int wanted);

// While alive, OpenBLAS runs every call on the calling thread with `threads` threads
// (openblas_set_num_threads; the previous count is restored after). The multifrontal
// factorization runs independent subtrees on separate threads, each with a one-thread
// BLAS. Nothing when the BLAS is not OpenBLAS.
class ScopedBlasThreads {
 public:
  explicit ScopedBlasThreads(int threads);
  ~ScopedBlasThreads();
  ScopedBlasThreads(const ScopedBlasThreads&) = delete;
  ScopedBlasThreads& operator=(const ScopedBlasThreads&) = delete;

 private:
  int previous_ = -1;  // openblas_get_num_threads() before, -1 without OpenBLAS
};

}  // namespace aster::linalg
