// The cells or nodes a factor keyword occurrence designates with TOUT,
// GROUP_MA, MAILLE, GROUP_NO, NOEUD (each once, in mesh order of appearance).
#pragma once
#include <vector>

#include "lang/keywords.hpp"
#include "mesh/mesh.hpp"

namespace aster::lang {

std::vector<int> selectCells(const mesh::Mesh& mesh, const Keywords& occ);
// Nodes of GROUP_NO / NOEUD, plus the nodes of the cells of TOUT / GROUP_MA / MAILLE.
std::vector<int> selectNodes(const mesh::Mesh& mesh, const Keywords& occ);

}  // namespace aster::lang
