#include "linalg/small_front.hpp"

#include "core/error.hpp"
#include "linalg/small_front_kernels.hpp"

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
      // and the OS saves its registers (the check includes it); every such CPU has AVX2 and FMA
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

FrontKernels frontKernelsInUse() {
  static const FrontKernels best = frontKernelsRun(FrontKernels::Avx512) ? FrontKernels::Avx512
                                   : frontKernelsRun(FrontKernels::Avx2) ? FrontKernels::Avx2
                                                                         : FrontKernels::Blas;
  return best;
}

const char* frontKernelsName(FrontKernels kernels) {
  switch (kernels) {
    case FrontKernels::Avx512: return "AVX-512";
    case FrontKernels::Avx2: return "AVX2 + FMA";
    case FrontKernels::Blas: break;
  }
  return "BLAS";
}

namespace {
void requireRunnable(FrontKernels kernels) {
  if (!frontKernelsRun(kernels))
    throw Error(std::string("front kernels: this build or this CPU does not run the ") + frontKernelsName(kernels) +
                " kernels");
}
}  // namespace

int smallFrontFactor(int width, int m, double* block, FrontKernels kernels) {
  requireRunnable(kernels);
#ifdef ASTER_AVX512_FRONTS
  if (kernels == FrontKernels::Avx512) return avx512::frontFactor(width, m, block);
#endif
#ifdef ASTER_AVX2_FRONTS
  if (kernels == FrontKernels::Avx2) return avx2::frontFactor(width, m, block);
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

void smallFrontUpdate(int u, int width, const double* L21, int ld, double* U, double* workspace,
                      FrontKernels kernels) {
  requireRunnable(kernels);
#ifdef ASTER_AVX512_FRONTS
  if (kernels == FrontKernels::Avx512) return avx512::frontUpdate(u, width, L21, ld, U, workspace);
#endif
#ifdef ASTER_AVX2_FRONTS
  if (kernels == FrontKernels::Avx2) return avx2::frontUpdate(u, width, L21, ld, U, workspace);
#endif
  (void)workspace;
  const double minusOne = -1.0, zero = 0.0;
  dsyrk_("L", "N", &u, &width, &minusOne, L21, &ld, &zero, U, &u);
}

std::size_t smallFrontWorkspace(int u, int width) {
  return static_cast<std::size_t>(packedRows(u)) * static_cast<std::size_t>(width);
}

}  // namespace aster::linalg
