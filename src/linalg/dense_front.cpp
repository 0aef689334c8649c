#include "linalg/dense_front.hpp"

#include <atomic>
#include <string>

#include "core/error.hpp"
#include "linalg/dense_front_kernels.hpp"

extern "C" {
void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info);
void dtrsm_(const char* side, const char* uplo, const char* transa, const char* diag, const int* m, const int* n,
            const double* alpha, const double* a, const int* lda, double* b, const int* ldb);
void dsyrk_(const char* uplo, const char* trans, const int* n, const int* k, const double* alpha, const double* a,
            const int* lda, const double* beta, double* c, const int* ldc);
}

namespace aster::linalg {

bool frontKernelsRun(FrontKernels kernels) {
  switch (kernels) {
    case FrontKernels::Blas:
      return true;
    case FrontKernels::Avx2: {
#ifdef ASTER_AVX2_FRONTS
      static const bool cpuHasAvx2Fma = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
      return cpuHasAvx2Fma;
#else
      return false;
#endif
    }
    case FrontKernels::Avx512: {
#ifdef ASTER_AVX512_FRONTS
      // The check includes the OS's saving of the registers; every such CPU has AVX2 and FMA.
      static const bool cpuHasAvx512 = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx2") &&
                                       __builtin_cpu_supports("fma");
      return cpuHasAvx512;
#else
      return false;
#endif
    }
  }
  return false;
}

namespace {
std::atomic<FrontKernels>& chosenKernels() {
  static std::atomic<FrontKernels> chosen{frontKernelsRun(FrontKernels::Avx512) ? FrontKernels::Avx512
                                          : frontKernelsRun(FrontKernels::Avx2) ? FrontKernels::Avx2
                                                                                : FrontKernels::Blas};
  return chosen;
}
}  // namespace

FrontKernels frontKernelsInUse() { return chosenKernels().load(std::memory_order_relaxed); }


const char* frontKernelsName(FrontKernels kernels) {
  switch (kernels) {
    case FrontKernels::Avx512: return "AVX-512";
    case FrontKernels::Avx2: return "AVX2 + FMA";
    case FrontKernels::Blas: break;
  }
  return "BLAS";
}

std::size_t frontWorkspace(int rows) {
  return static_cast<std::size_t>(packedRows(rows > 0 ? rows : 0)) * static_cast<std::size_t>(kDepth);
}

namespace {

void requireRunnable(FrontKernels kernels, bool blasToo) {
  if (!frontKernelsRun(kernels) || (!blasToo && kernels == FrontKernels::Blas))
    throw Error(std::string("dense front kernels: this build or this CPU does not run the ") +
                frontKernelsName(kernels) + " kernels" + (blasToo ? "" : " for pieces of a front"));
}

// The build's function `name` with `args`: AVX-512 or AVX2 (the caller checked which runs).
#if defined(ASTER_AVX512_FRONTS) && defined(ASTER_AVX2_FRONTS)
#define ASTER_CALL_KERNELS(kernels, name, ...) \
  ((kernels) == FrontKernels::Avx512 ? avx512::name(__VA_ARGS__) : avx2::name(__VA_ARGS__))
#elif defined(ASTER_AVX2_FRONTS)
#define ASTER_CALL_KERNELS(kernels, name, ...) avx2::name(__VA_ARGS__)
#elif defined(ASTER_AVX512_FRONTS)
#define ASTER_CALL_KERNELS(kernels, name, ...) avx512::name(__VA_ARGS__)
#endif

}  // namespace

void useFrontKernels(FrontKernels kernels) {
  requireRunnable(kernels, true);
  chosenKernels().store(kernels, std::memory_order_relaxed);
}

int factorFront(int width, int m, double* block, double* workspace, FrontKernels kernels) {
  requireRunnable(kernels, true);
#ifdef ASTER_CALL_KERNELS
  if (kernels != FrontKernels::Blas) return ASTER_CALL_KERNELS(kernels, frontFactor, width, m, block, workspace);
#endif
  int info = 0;
  dpotrf_("L", &width, block, &m, &info);
  const int u = m - width;
  if (info == 0 && u > 0) {
    const double one = 1.0;
    dtrsm_("R", "L", "T", "N", &u, &width, &one, block, &m, block + width, &m);
  }
  return info;
}

void updateMatrix(int u, int width, const double* L21, int ld, double* U, double* workspace, FrontKernels kernels) {
  requireRunnable(kernels, true);
#ifdef ASTER_CALL_KERNELS
  if (kernels != FrontKernels::Blas)
    return ASTER_CALL_KERNELS(kernels, subtractLowerProducts, u, 0, u, width, L21, ld, U, u, workspace, true);
#endif
  const double minusOne = -1.0, zero = 0.0;
  dsyrk_("L", "N", &u, &width, &minusOne, L21, &ld, &zero, U, &u);
}

int factorDiagonalBlock(int width, int ld, double* diag, FrontKernels kernels) {
  requireRunnable(kernels, false);
#ifdef ASTER_CALL_KERNELS
  return ASTER_CALL_KERNELS(kernels, factorDiagonal, width, ld, diag);
#else
  (void)width, (void)ld, (void)diag;
  return 0;  // not reached: requireRunnable threw
#endif
}

void solveRowsBelow(int width, int ld, const double* diag, int rows, double* part, FrontKernels kernels) {
  requireRunnable(kernels, false);
#ifdef ASTER_CALL_KERNELS
  ASTER_CALL_KERNELS(kernels, solveRows, width, ld, diag, rows, part);
#else
  (void)width, (void)ld, (void)diag, (void)rows, (void)part;
#endif
}

void subtractLowerProducts(int rows, int c0, int c1, int k, const double* A, int lda, double* C, int ldc,
                           double* workspace, bool assign, FrontKernels kernels) {
  requireRunnable(kernels, false);
#ifdef ASTER_CALL_KERNELS
  ASTER_CALL_KERNELS(kernels, subtractLowerProducts, rows, c0, c1, k, A, lda, C, ldc, workspace, assign);
#else
  (void)rows, (void)c0, (void)c1, (void)k, (void)A, (void)lda, (void)C, (void)ldc, (void)workspace, (void)assign;
#endif
}

}  // namespace aster::linalg
