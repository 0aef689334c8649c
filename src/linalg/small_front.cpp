#include "linalg/small_front.hpp"

#include "linalg/small_front_avx2.hpp"

extern "C" {
void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info);
void dtrsm_(const char* side, const char* uplo, const char* transa, const char* diag, const int* m, const int* n,
            const double* alpha, const double* a, const int* lda, double* b, const int* ldb);
void dsyrk_(const char* uplo, const char* trans, const int* n, const int* k, const double* alpha, const double* a,
            const int* lda, const double* beta, double* c, const int* ldc);
}

namespace aster::linalg {

bool smallFrontKernels() {
#ifdef ASTER_AVX2_FRONTS
  static const bool cpuHasAvx2Fma = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return cpuHasAvx2Fma;
#else
  return false;
#endif
}

int smallFrontFactor(int width, int m, double* block) {
#ifdef ASTER_AVX2_FRONTS
  if (smallFrontKernels()) return avx2::frontFactor(width, m, block);
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

void smallFrontUpdate(int u, int width, const double* L21, int ld, double* U, double* workspace) {
#ifdef ASTER_AVX2_FRONTS
  if (smallFrontKernels()) return avx2::frontUpdate(u, width, L21, ld, U, workspace);
#endif
  (void)workspace;
  const double minusOne = -1.0, zero = 0.0;
  dsyrk_("L", "N", &u, &width, &minusOne, L21, &ld, &zero, U, &u);
}

std::size_t smallFrontWorkspace(int u, int width) {
  return static_cast<std::size_t>(avx2::packedRows(u)) * static_cast<std::size_t>(width);
}

}  // namespace aster::linalg
