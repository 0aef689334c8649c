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
// and the CPU and the OS support AVX-512 (or AVX2), this switches OpenBLAS to its SkylakeX
// (or Haswell) kernels in the running process (switchBlasKernels). Call it before any BLAS
// call, while no other thread uses the BLAS (first thing in main()).
void selectBlasKernels();

// The kernels selectBlasKernels gives a library that reports `core`: "SkylakeX" or "Haswell"
// when `core` is Prescott and this CPU and its OS run AVX-512 (or AVX2 + FMA), null otherwise.
const char* betterBlasKernels(const std::string& core);

// Makes OpenBLAS use the kernels of `core` (a name OPENBLAS_CORETYPE accepts). OpenBLAS
// reads OPENBLAS_CORETYPE only in its start-up routine (gotoblas_dynamic_init, exported by
// the builds for several CPUs); this runs that routine again with the variable set, then
// restores the environment as it was (no child process inherits the variable). Returns
// whether OpenBLAS now reports `core`; false without that routine (another BLAS, or an
// OpenBLAS built for one CPU). Same conditions as selectBlasKernels.
bool switchBlasKernels(const char* core);

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
// solver needs no BLAS thread (multifrontal_cholesky.cpp), so main() calls this
// first: it records the count OpenBLAS chose (startupBlasThreads), sets one thread
// and stops the workers (blas_thread_shutdown_, OpenBLAS's own routine for fork);
// OpenBLAS creates them again when chooseBlasThreads asks for more than one thread
// (large systems). Nothing when the user chose the count (OPENBLAS_NUM_THREADS,
// OMP_NUM_THREADS) or when the BLAS is not OpenBLAS. The environment is not touched.
void startBlasOnOneThread();

// The count OpenBLAS chose when it was loaded (before startBlasOnOneThread): all cores
// unless the user set it; 1 for another BLAS.
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
