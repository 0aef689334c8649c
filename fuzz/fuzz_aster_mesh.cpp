// libFuzzer target: the ASTER (.mail) mesh reader. Any input must either give
// a mesh or throw aster::Error; anything else (a crash, a sanitizer report,
// another exception, a hang) is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "mesh/io/aster_format.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const aster::mesh::Mesh m = aster::mesh::parseAsterMesh(text, "fuzz.mail");
    // What was read must be consistent: every cell node is a node of the mesh.
    for (int c = 0; c < m.cellCount(); ++c)
      for (int n : m.cellNodes(c))
        if (n < 0 || n >= m.nodeCount()) __builtin_trap();
  } catch (const aster::Error&) {
  }
  return 0;
}
