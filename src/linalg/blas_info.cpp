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

std::string lowercase(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::string openblasCore() {
  using TextFunction = char* (*)();
  auto corename = reinterpret_cast<TextFunction>(dlsym(RTLD_DEFAULT, "openblas_get_corename"));
  return corename ? corename() : "";
}

}  // namespace

const char* betterBlasKernels(const std::string& core) {
#if defined(__x86_64__)
  if (lowercase(core) != "prescott") return nullptr;  // OpenBLAS knew the CPU
  const std::uint64_t xcr0 = osSavedState();
  if ((xcr0 & 0xe6) == 0xe6 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
      __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq"))
    return "SkylakeX";
  if ((xcr0 & 0x6) == 0x6 && __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) return "Haswell";
#else
  (void)core;
#endif
  return nullptr;
}

bool switchBlasKernels(const char* core) {
  using Routine = void (*)();
  auto forget = reinterpret_cast<Routine>(dlsym(RTLD_DEFAULT, "gotoblas_dynamic_quit"));
  auto start = reinterpret_cast<Routine>(dlsym(RTLD_DEFAULT, "gotoblas_dynamic_init"));
  if (!forget || !start || openblasCore().empty()) return false;
  const char* before = getenv("OPENBLAS_CORETYPE");
  const std::string userValue = before ? before : "";
  setenv("OPENBLAS_CORETYPE", core, 1);
  forget();  // the start-up routine does nothing while kernels are chosen
  start();
  if (before)
    setenv("OPENBLAS_CORETYPE", userValue.c_str(), 1);
  else
    unsetenv("OPENBLAS_CORETYPE");
  return lowercase(openblasCore()) == lowercase(core);
}

void selectBlasKernels() {
  if (getenv("OPENBLAS_CORETYPE")) return;  // the user's choice
  if (const char* better = betterBlasKernels(openblasCore())) switchBlasKernels(better);
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

bool userChoseBlasThreads() { return getenv("OPENBLAS_NUM_THREADS") || getenv("OMP_NUM_THREADS"); }

// After blas_thread_shutdown_, openblas_set_num_threads creates the workers again whatever
// the count asked, one included: it is called only when the count changes.
void setBlasThreads(const BlasThreadCount& blas, int threads) {
  if (blas.get() != threads) blas.set(threads);
}
}  // namespace

int startupBlasThreads() {
  const BlasThreadCount& blas = blasThreads();
  if (!blas.get) return 1;
  static const int count = blas.get();  // read once, before any change to the count
  return count;
}

void startBlasOnOneThread() {
  const BlasThreadCount& blas = blasThreads();
  if (!blas.get || userChoseBlasThreads() || startupBlasThreads() <= 1) return;
  blas.set(1);
  using Routine = void (*)();
  if (auto stopWorkers = reinterpret_cast<Routine>(dlsym(RTLD_DEFAULT, "blas_thread_shutdown_"))) stopWorkers();
}

void chooseBlasThreads(int unknowns) {
  const BlasThreadCount& blas = blasThreads();
  if (!blas.get || userChoseBlasThreads()) return;
  setBlasThreads(blas, unknowns < kSmallSystem ? 1 : blasCallersThatFit(startupBlasThreads()));
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
  setBlasThreads(blas, threads);
}

ScopedBlasThreads::~ScopedBlasThreads() {
  if (previous_ > 0) setBlasThreads(blasThreads(), previous_);
}

}  // namespace aster::linalg
