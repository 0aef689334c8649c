// libFuzzer target: the gmsh MSH 1 / MSH 2 ASCII reader of PRE_GMSH. Any input
// must either give a mesh or throw aster::Error; anything else (a crash, a
// sanitizer report, another exception, a hang) is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "mesh/io/pre_gmsh_format.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const aster::mesh::Mesh m = aster::mesh::parseGmshAsPreGmsh(text, "fuzz.msh");
    for (int c = 0; c < m.cellCount(); ++c)
      for (int n : m.cellNodes(c))
        if (n < 0 || n >= m.nodeCount()) __builtin_trap();
  } catch (const aster::Error&) {
  }
  return 0;
}
