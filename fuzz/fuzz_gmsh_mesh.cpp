// libFuzzer target: the GMSH path aster-lite owns. The input is written to a
// .msh file that gmsh (the Debian library, not instrumented) parses; what
// aster-lite does with gmsh's model (entities, physical groups, node ordering,
// undefined nodes) is instrumented. Any input must either give a consistent
// mesh or throw aster::Error; a crash, a sanitizer report or another exception
// is a finding.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "core/error.hpp"
#include "mesh/io/gmsh_format.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string path = "/tmp/aster-fuzz-gmsh-" + std::to_string(::getpid()) + ".msh";
  if (FILE* f = std::fopen(path.c_str(), "wb")) {
    std::fwrite(data, 1, size, f);
    std::fclose(f);
  } else {
    return 0;
  }
  try {
    const aster::mesh::Mesh m = aster::mesh::readGmshMesh(path);
    for (int c = 0; c < m.cellCount(); ++c)
      for (int n : m.cellNodes(c))
        if (n < 0 || n >= m.nodeCount()) __builtin_trap();
  } catch (const aster::Error&) {
  }
  return 0;
}
