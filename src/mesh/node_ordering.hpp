// Node-order conversions between code_aster and other conventions (MED, gmsh,
// VTK). A permutation p maps: asterNodes[j] = otherNodes[p[j]].
#pragma once
#include <vector>

#include "mesh/cell_type.hpp"

namespace aster::mesh {

enum class NodeConvention { Med, Gmsh, Vtk };

// Permutation such that asterNodes[j] = foreign[p[j]]; identity when both agree.
// Throws aster::Error when the convention has no such cell type.
const std::vector<int>& asterFromForeign(NodeConvention convention, CellType type);

// Reorders a cell's nodes read in another convention into code_aster's order, and back.
std::vector<int> toAsterOrder(NodeConvention convention, CellType type, const std::vector<int>& foreign);
std::vector<int> fromAsterOrder(NodeConvention convention, CellType type, const std::vector<int>& aster);

}  // namespace aster::mesh
