// VTK output for ParaView: .vtu (XML, ASCII) with nodal point data, and a .pvd
// collection listing one .vtu per instant.
#pragma once
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/nodal_field.hpp"

namespace aster::mesh {

// Fields of 2 components are padded to 3 (ParaView vectors). Point data named
// by field; a "cell type" cell array is not written.
void writeVtu(const Mesh& mesh, const std::string& path, const std::vector<NodalField>& fields = {});

// Writes <stem>_<k>.vtu per instant next to `pvdPath` and the collection file.
void writePvd(const Mesh& mesh, const std::string& pvdPath, const std::vector<FieldInstant>& instants);

// The collection file alone: one data set per instant, files named relative to it.
struct PvdEntry {
  double time = 0.0;
  std::string file;
};
void writePvdCollection(const std::string& pvdPath, const std::vector<PvdEntry>& entries);

}  // namespace aster::mesh
