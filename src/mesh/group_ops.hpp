// DEFI_GROUP operations: combining groups of cells, groups of nodes from cells,
// and NOEUD_ORDO (the nodes of a chain of segments from one end to the other).
#pragma once
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace aster::mesh {

// Cells of all the groups, each once, in order of first appearance.
std::vector<int> unionOfCellGroups(const Mesh& mesh, const std::vector<std::string>& groups);
// Cells of the first group that are in every other group (first group's order).
std::vector<int> intersectionOfCellGroups(const Mesh& mesh, const std::vector<std::string>& groups);
// Cells of the first group that are in none of the others (first group's order).
std::vector<int> differenceOfCellGroups(const Mesh& mesh, const std::vector<std::string>& groups);
// Nodes of the cells of the groups, each once, in order of first appearance.
std::vector<int> nodesOfCellGroups(const Mesh& mesh, const std::vector<std::string>& groups);

// For each cell, the indices in mesh.cellGroupNames() of the groups it belongs to, ascending.
std::vector<std::vector<int>> groupsOfEachCell(const Mesh& mesh);

// NOEUD_ORDO: the nodes of the segments (SEG2, SEG3, SEG4) `cells`, which must form
// one open chain, from one end to the other, inner nodes of SEG3/SEG4 in
// geometric order. The chain is walked from `startNode` when given (it must be
// an end), else in the direction of the first cell of `cells` (first node to second).
std::vector<int> orderedChainNodes(const Mesh& mesh, const std::vector<int>& cells, int startNode = -1);

}  // namespace aster::mesh
