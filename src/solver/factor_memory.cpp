#include "solver/factor_memory.hpp"

#include <malloc.h>

namespace aster::solver {

void keepFactorWorkspaces() {
  // Setting them fixes both thresholds (glibc stops adjusting them by itself).
  mallopt(M_MMAP_THRESHOLD, 64 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
}

}  // namespace aster::solver
