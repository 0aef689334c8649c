// gmsh meshes as code_aster's PRE_GMSH converts them (U7.01.31), read by
// aster-lite itself: MSH 1 ($NOD / $ENDNOD, $ELM / $ENDELM) and MSH 2 ASCII
// ($MeshFormat 2.x 0 8, $Nodes, $Elements).
//
// - Nodes are named N<gmsh number>, cells M<gmsh number>; only the nodes of
//   the cells are kept; the mesh is 3D (COOR_3D), in the order of the file.
// - Cells come by gmsh type (1, 2, 3, ... 19), in file order within a type; node
//   order is converted to code_aster's. gmsh's QUAD9 (10) becomes a QUAD8 and
//   its 14-node pyramid (14) a PYRAM13: PRE_GMSH drops their centre node.
// - Each physical tag p (the first tag in MSH 2) gives the group of cells
//   GM<p>, plus the group of nodes GM<p> when it holds one POI1 cell only;
//   the elementary tag and physical names are not used; cells of physical
//   tag 0 are in no group.
#pragma once
#include <string>

#include "mesh/mesh.hpp"

namespace aster::mesh {

// True for the versions LIRE_MAILLAGE{FORMAT='GMSH'} reads as PRE_GMSH does
// rather than through gmsh's library (which reads 2.2 and 4.x): MSH 1 (the
// file starts with $NOD) and MSH 2.0 / 2.1 ($MeshFormat 2 or 2.1).
bool isPreGmshOnlyFile(const std::string& path);

// Throws aster::Error "<file>:<line>: <what was expected>" on malformed input
// and for a file of another version (MSH 4, binary).
Mesh readGmshAsPreGmsh(const std::string& path);
Mesh parseGmshAsPreGmsh(const std::string& text, const std::string& sourceName);

}  // namespace aster::mesh
