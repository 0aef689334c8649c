// The cells or nodes a factor keyword occurrence designates with TOUT,
// GROUP_MA, MAILLE, GROUP_NO, NOEUD, less those of SANS_GROUP_MA, SANS_MAILLE,
// SANS_GROUP_NO, SANS_NOEUD (each once, in mesh order of appearance). The
// catalogue says which of these keywords a command takes.
#pragma once
#include <string>
#include <vector>

#include "lang/keywords.hpp"
#include "mesh/mesh.hpp"

namespace aster::lang {

// TOUT, GROUP_MA, MAILLE, less SANS_GROUP_MA, SANS_MAILLE.
std::vector<int> selectCells(const mesh::Mesh& mesh, const Keywords& occ);
// Nodes of GROUP_NO / NOEUD, plus the nodes of the cells of TOUT / GROUP_MA / MAILLE,
// less the nodes of SANS_GROUP_NO, SANS_NOEUD and of the cells of SANS_GROUP_MA, SANS_MAILLE.
std::vector<int> selectNodes(const mesh::Mesh& mesh, const Keywords& occ);
// The nodes SANS_GROUP_NO, SANS_NOEUD, SANS_GROUP_MA, SANS_MAILLE leave out (may repeat).
std::vector<int> excludedNodes(const mesh::Mesh& mesh, const Keywords& occ);

// The nodes (cells) named by the keyword `key` of the occurrence (NOEUD, SANS_NOEUD,
// NOEUD_ORIG, ...), in the order given; none when the keyword is absent. A name the
// mesh lacks is an error naming the occurrence, the keyword, the name and the closest names.
std::vector<int> namedNodes(const mesh::Mesh& mesh, const Keywords& occ, const std::string& key);
std::vector<int> namedCells(const mesh::Mesh& mesh, const Keywords& occ, const std::string& key);
int namedNode(const mesh::Mesh& mesh, const Keywords& occ, const std::string& key, const std::string& name);
int namedCell(const mesh::Mesh& mesh, const Keywords& occ, const std::string& key, const std::string& name);

}  // namespace aster::lang
