// Building a mesh whose cells replace some cells of another by children (MACR_ADAP_MAIL's
// refinement, CREA_MAILLAGE's DECOUPE_LAC): the cells and the cell groups of the new mesh.
#pragma once
#include <utility>
#include <vector>

#include "mesh/mesh.hpp"

namespace aster::mesh {

// A cell's children: their types and nodes (numbers of the new mesh); none: the cell stays.
using CellChildren = std::vector<std::pair<CellType, std::vector<int>>>;

// Adds to `out` (its nodes already there, numbered as `in`'s where kept) every cell of `in`,
// or its children when children[c] has some, in the order of `in`'s cells. Kept cells keep
// their names; children are named M1, M2, ..., skipping the names kept. Then the cell groups
// of `in`, each child in place of its parent. Returns the new cells of each cell of `in`.
std::vector<std::vector<int>> addCellsAndChildren(const Mesh& in, const std::vector<CellChildren>& children,
                                                  Mesh& out);

}  // namespace aster::mesh
