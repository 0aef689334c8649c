// libFuzzer target: the GMSH reader path aster-lite owns, i.e. checkMshFile,
// the structural check every .msh file passes before it reaches the gmsh
// library. Any input must either pass or throw aster::Error; a crash, a
// sanitizer report, another exception or a hang is a finding.
// gmsh itself (Debian's library, not instrumented) is left out on purpose: it
// leaks what it has read when it gives up on a malformed file, and it
// allocates by the counts and tags a file announces (a valid file with a node
// tag of 10^9 costs gigabytes), so fuzzing it only measures gmsh.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "core/error.hpp"
#include "mesh/io/msh_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string path = "/tmp/aster-fuzz-gmsh-" + std::to_string(::getpid()) + ".msh";
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  std::fwrite(data, 1, size, f);
  std::fclose(f);
  try {
    aster::mesh::checkMshFile(path);
  } catch (const aster::Error&) {
  }
  return 0;
}
