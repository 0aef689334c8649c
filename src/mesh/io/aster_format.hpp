// code_aster's native text mesh format (.mail): TITRE, COOR_1D/2D/3D, one
// section per cell type, GROUP_NO / GROUP_MA, each ended by FINSF, file ended
// by FIN; '%' starts a comment; entries may wrap over several lines.
#pragma once
#include <iosfwd>
#include <string>

#include "mesh/mesh.hpp"

namespace aster::mesh {

// Throws aster::Error "<file>:<line>: <what was expected>" on malformed input.
Mesh readAsterMesh(const std::string& path);
// Same, from text already in memory; sourceName is used in messages.
Mesh parseAsterMesh(const std::string& text, const std::string& sourceName);

void writeAsterMesh(const Mesh& mesh, const std::string& path);
void writeAsterMesh(const Mesh& mesh, std::ostream& out);

}  // namespace aster::mesh
