// Uniform refinement (MACR_ADAP_MAIL ADAPTATION='RAFFINEMENT_UNIFORME').
#pragma once
#include <vector>

#include "mesh/mesh.hpp"

namespace aster::mesh {

// Splits each 2D cell (TRIA3, TRIA6, QUAD4, QUAD8, QUAD9) of `cells` (every 2D
// cell when empty) into 4 of the same type and each SEG2/SEG3 lying on a split
// edge into 2. Other cells are copied unchanged (with their names). Old nodes
// keep their index and name; new nodes are placed through the parent's
// isoparametric map (curved edges stay on their curve). Groups of cells list
// the children in place of their parent. A group of nodes whose nodes are
// exactly those of a group of cells follows it: it becomes the nodes of the
// refined cells (in chain order if it was the NOEUD_ORDO chain of those
// segments); a group no new node lies between (points) is unchanged.
// Throws aster::Error for a cell of `cells` that cannot be split (TRIA7, 1D,
// 3D), and for the other groups of nodes, naming them: a new node lies between
// their nodes and nothing tells whether it belongs to them.
Mesh refineUniformly(const Mesh& mesh, const std::vector<int>& cells = {});

}  // namespace aster::mesh
