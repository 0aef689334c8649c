#include "linalg/blas_info.hpp"

#include <dlfcn.h>
#include <limits.h>
#include <stdlib.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cctype>
#include <cstddef>
#include <cstdint>
#include <string>

namespace aster::linalg {

BlasInfo blasInUse() {
  BlasInfo info;
  void* dgemm = dlsym(RTLD_DEFAULT, "dgemm_");
  Dl_info where;
  if (dgemm && dladdr(dgemm, &where) && where.dli_fname) {
    char resolved[PATH_MAX];
    info.library = realpath(where.dli_fname, resolved) ? resolved : where.dli_fname;
  }
  using TextFunction = char* (*)();
  using IntFunction = int (*)();
  if (auto config = reinterpret_cast<TextFunction>(dlsym(RTLD_DEFAULT, "openblas_get_config")))
    info.openblasConfig = config();
  if (auto core = reinterpret_cast<TextFunction>(dlsym(RTLD_DEFAULT, "openblas_get_corename")))
    info.openblasCore = core();
  if (auto threads = reinterpret_cast<IntFunction>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads")))
    info.threads = threads();
  return info;
}

namespace {

#if defined(__x86_64__)
// Register state the OS saves on context switches (XCR0): bits 1-2 SSE/AVX, 5-7 AVX-512.
std::uint64_t osSavedState() {
  __builtin_cpu_init();
  unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
  __asm__("cpuid" : "=a"(eax), "=b"(ebx), "=c"(ecx), "=d"(edx) : "a"(1), "c"(0));
  if (!(ecx & (1u << 27))) return 0;  // no OSXSAVE
  unsigned lo = 0, hi = 0;
  __asm__("xgetbv" : "=a"(lo), "=d"(hi) : "c"(0));
  return (static_cast<std::uint64_t>(hi) << 32) | lo;
}
#endif

}  // namespace

void selectBlasKernels(char** argv) {
#if defined(__x86_64__)
  if (getenv("OPENBLAS_CORETYPE") || getenv("ASTER_BLAS_SELECTED")) return;
  using TextFunction = char* (*)();
  auto corename = reinterpret_cast<TextFunction>(dlsym(RTLD_DEFAULT, "openblas_get_corename"));
  if (!corename) return;
  std::string core = corename();
  for (char& c : core) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (core != "prescott") return;  // OpenBLAS knew the CPU
  const std::uint64_t xcr0 = osSavedState();
  const char* choice = nullptr;
  if ((xcr0 & 0xe6) == 0xe6 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
      __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq"))
    choice = "SkylakeX";
  else if ((xcr0 & 0x6) == 0x6 && __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
    choice = "Haswell";
  if (!choice) return;
  setenv("OPENBLAS_CORETYPE", choice, 1);
  setenv("ASTER_BLAS_SELECTED", "1", 1);  // never loop
  startBlasOnOneThread();
  execv("/proc/self/exe", argv);
  // exec failed: go on with the generic kernels
#else
  (void)argv;
#endif
}

namespace {
// OpenBLAS's thread count, looked up at run time: getter and setter both null when the BLAS
// is another.
struct BlasThreadCount {
  int (*get)() = reinterpret_cast<int (*)()>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  void (*set)(int) = reinterpret_cast<void (*)(int)>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  BlasThreadCount() {
    if (!get || !set) {
      get = nullptr;
      set = nullptr;
    }
  }
};
const BlasThreadCount& blasThreads() {
  static const BlasThreadCount count;
  return count;
}

// Set by startBlasOnOneThread for the re-executed process: the count OpenBLAS chose before.
constexpr const char* kChosenThreads = "ASTER_BLAS_THREADS";

bool userChoseBlasThreads() {
  return (getenv("OPENBLAS_NUM_THREADS") || getenv("OMP_NUM_THREADS")) && !getenv(kChosenThreads);
}
}  // namespace

void startBlasOnOneThread() {
  const BlasThreadCount& blas = blasThreads();
  if (!blas.get || userChoseBlasThreads() || getenv(kChosenThreads)) return;
  setenv(kChosenThreads, std::to_string(blas.get()).c_str(), 1);
  setenv("OPENBLAS_NUM_THREADS", "1", 1);
}

int startupBlasThreads() {
  const BlasThreadCount& blas = blasThreads();
  if (!blas.get) return 1;
  // Read once, before any change to the count.
  static const int count = [&] {
    const char* chosen = getenv(kChosenThreads);
    const int n = chosen ? std::atoi(chosen) : 0;
    return n > 0 ? n : blas.get();
  }();
  return count;
}

void chooseBlasThreads(int unknowns) {
  const BlasThreadCount& blas = blasThreads();
  if (!blas.get || userChoseBlasThreads()) return;
  blas.set(unknowns < kSmallSystem ? 1 : blasCallersThatFit(startupBlasThreads()));
}

namespace {
// BUFFER_SIZE of OpenBLAS on x86-64 (common_x86_64.h: 32 << 22), with a page of slack.
constexpr std::size_t kBlasBuffer = (std::size_t{32} << 22) + 4096;

bool addressSpaceLimited() {
  static const bool limited = [] {
    rlimit limit{};
    return dlsym(RTLD_DEFAULT, "openblas_get_config") && getrlimit(RLIMIT_AS, &limit) == 0 &&
           limit.rlim_cur != RLIM_INFINITY;
  }();
  return limited;
}

// Whether `bytes` more of address space can be mapped now (mapped, then given back).
bool addressSpaceLeft(std::size_t bytes) {
  void* p = mmap(nullptr, bytes, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
  if (p == MAP_FAILED) return false;
  munmap(p, bytes);
  return true;
}
}  // namespace

std::string reserveBlasBuffer() {
  if (!addressSpaceLimited()) return "";
  using Potrf = void (*)(const char*, const int*, double*, const int*, int*);
  auto potrf = reinterpret_cast<Potrf>(dlsym(RTLD_DEFAULT, "dpotrf_"));
  if (!potrf) return "";
  if (!addressSpaceLeft(kBlasBuffer)) {
    rlimit limit{};
    getrlimit(RLIMIT_AS, &limit);
    return "not enough memory: the address space is limited to " + std::to_string(limit.rlim_cur >> 20) +
           " MiB (ulimit -v, prlimit --as), too little for OpenBLAS's work buffer of " +
           std::to_string(kBlasBuffer >> 20) + " MiB";
  }
  double one = 1.0;  // a 1 x 1 factorization: OpenBLAS maps its buffer and keeps it
  const int n = 1;
  int info = 0;
  potrf("L", &n, &one, &n, &info);
  return "";
}

int blasCallersThatFit(int wanted) {
  if (wanted <= 1 || !addressSpaceLimited()) return wanted;
  // The first buffer is there (reserveBlasBuffer); room for the others, as many as fit.
  // Buffers OpenBLAS already mapped for earlier calls are counted as new: fewer
  // threads than possible, never a hang.
  for (int more = wanted - 1; more > 0; --more)
    if (addressSpaceLeft(static_cast<std::size_t>(more) * kBlasBuffer)) return more + 1;
  return 1;
}

ScopedBlasThreads::ScopedBlasThreads(int threads) {
  const BlasThreadCount& blas = blasThreads();
  if (!blas.get) return;
  previous_ = blas.get();
  if (previous_ != threads) blas.set(threads);
}

ScopedBlasThreads::~ScopedBlasThreads() {
  if (previous_ > 0 && previous_ != blasThreads().get()) blasThreads().set(previous_);
}

}  // namespace aster::linalg
