#include "solver/blas_info.hpp"

#include <dlfcn.h>
#include <limits.h>
#include <stdlib.h>

namespace aster::solver {

BlasInfo blasInUse() {
  BlasInfo info;
  void* dgemm = dlsym(RTLD_DEFAULT, "dgemm_");
  Dl_info where;
  if (dgemm && dladdr(dgemm, &where) && where.dli_fname) {
    char resolved[PATH_MAX];
    info.library = realpath(where.dli_fname, resolved) ? resolved : where.dli_fname;
  }
  using ConfigFunction = char* (*)();
  if (auto config = reinterpret_cast<ConfigFunction>(dlsym(RTLD_DEFAULT, "openblas_get_config")))
    info.openblasConfig = config();
  return info;
}

}  // namespace aster::solver
