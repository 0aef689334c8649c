#include "linalg/factor_memory.hpp"

#include <malloc.h>
#include <stdlib.h>
#include <unistd.h>

#include <fstream>
#include <string>

#include "linalg/blas_info.hpp"

namespace aster::linalg {

void keepFactorWorkspaces() {
  // Setting them fixes both thresholds (glibc stops adjusting them by itself).
  mallopt(M_MMAP_THRESHOLD, 64 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
}

void selectHugePages(char** argv) {
  if (getenv("ASTER_BLAS_SELECTED")) return;
  const char* current = getenv("GLIBC_TUNABLES");
  std::string tunables = current ? current : "";
  if (tunables.find("glibc.malloc.hugetlb") != std::string::npos) return;
  std::ifstream thp("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string modes;
  std::getline(thp, modes);
  if (modes.find("[madvise]") == std::string::npos) return;  // always: nothing to ask; never: no use
  tunables += std::string(tunables.empty() ? "" : ":") + "glibc.malloc.hugetlb=1";
  setenv("GLIBC_TUNABLES", tunables.c_str(), 1);
  startBlasOnOneThread();
  execv("/proc/self/exe", argv);
  // exec failed: go on with 4 KiB pages
}

}  // namespace aster::linalg
