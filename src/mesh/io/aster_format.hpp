// code_aster's native text mesh format (.mail): TITRE, COOR_1D/2D/3D, one
// section per cell type, GROUP_NO / GROUP_MA, each ended by FINSF, file ended
// by FIN; '%' starts a comment; entries may wrap over several lines.
// Read as code_aster reads it (U3.01.00): the words after a section keyword
// are KEY=VALUE items or free text; NOM= names a group, NBLIGE=n makes the
// header n lines long, the rest only describes the section and is ignored
// (a GROUP_MA / GROUP_NO line still refuses an unknown key, so that a misspelt
// NOM= is not silently read as code_aster would: the group named after the
// first word of the next line). In a section '=' separates words like a blank
// ("M2 = N1 N2"); FIN first on a line closes the open section and the file;
// an extra FINSF between sections is skipped.
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace aster::mesh {

// Throws aster::Error "<file>:<line>: <what was expected>" on malformed input.
// What is read but deserves a word to the user ("<file>:<line>: ...") goes
// to `alarms` when given.
Mesh readAsterMesh(const std::string& path, std::vector<std::string>* alarms = nullptr);
// The whole text of a mesh file (ASTER, GMSH's text formats); throws aster::Error
// naming the file when it cannot be opened or read.
std::string meshFileText(const std::string& path);
// Same, from text already in memory; sourceName is used in messages.
Mesh parseAsterMesh(const std::string& text, const std::string& sourceName,
                    std::vector<std::string>* alarms = nullptr);

void writeAsterMesh(const Mesh& mesh, const std::string& path);
void writeAsterMesh(const Mesh& mesh, std::ostream& out);

}  // namespace aster::mesh
