// Which BLAS the process uses (CHOLMOD's supernodal factorization calls dgemm/dsyrk/dpotrf).
// CHOLMOD links libblas.so.3, which Debian's alternatives system points at one
// implementation (reference BLAS or OpenBLAS); this reports the one actually loaded.
#pragma once
#include <string>

namespace aster::solver {

struct BlasInfo {
  std::string library;  // resolved file providing dgemm_, empty if no BLAS is loaded
  std::string openblasConfig;  // openblas_get_config() when OpenBLAS is loaded, empty otherwise
};

BlasInfo blasInUse();

}  // namespace aster::solver
