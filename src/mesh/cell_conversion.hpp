// Changes of cell type that keep the cells (CREA_MAILLAGE LINE_QUAD, QUAD_LINE,
// MODI_MAILLE): each returns a new mesh; the input is left unchanged. Cells
// keep their index and name, groups of cells are copied as they are.
#pragma once
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace aster::mesh {

// LINE_QUAD: SEG2 -> SEG3, TRIA3 -> TRIA6, QUAD4 -> QUAD8 for the cells listed
// (other types among them are left as they are). A middle node is put at the
// midpoint of each edge, one per edge: cells sharing an edge share its node.
// New nodes are numbered in order of first appearance (cells in order, edges
// in code_aster order) and named <prefix><firstNumber>, <prefix><firstNumber+1>...
// Groups of nodes are copied unchanged (the new nodes join none), as code_aster
// does. Throws aster::Error when a new name is already a node's.
Mesh lineToQuadratic(const Mesh& mesh, const std::vector<int>& cells, const std::string& prefix, int firstNumber);

// QUAD_LINE: SEG3 -> SEG2, TRIA6 -> TRIA3, QUAD8/QUAD9 -> QUAD4 for the cells
// listed (other types left as they are). The nodes they drop that no cell uses
// any more are removed, and from the groups of nodes; the other nodes keep
// their names and order.
Mesh quadraticToLinear(const Mesh& mesh, const std::vector<int>& cells);

// MODI_MAILLE OPTION='QUAD8_9' (QUAD8 -> QUAD9) or 'TRIA6_7' (TRIA6 -> TRIA7)
// for the cells listed of the type converted (others left as they are): a
// centre node is added per cell at the image of the reference centre by the
// cell's isoparametric map, named <prefix><firstNumber>, ... in cell order.
// Groups are copied unchanged. Throws aster::Error for another option.
Mesh addCentreNodes(const Mesh& mesh, const std::vector<int>& cells, const std::string& option,
                    const std::string& prefix, int firstNumber);

}  // namespace aster::mesh
