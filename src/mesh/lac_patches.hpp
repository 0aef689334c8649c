// CREA_MAILLAGE DECOUPE_LAC in 2D: prepares the slave side of a contact zone
// for the LAC (mortar) method. Each slave segment becomes one patch; the
// linear cells are cut so that a patch holds several slave segments:
//  - SEG2 on a TRIA3: the segment is split at its midpoint (new node C<k>) and
//    the triangle in two from that node to its opposite vertex;
//  - SEG2 on a QUAD4: the segment is split in three at reference -1/3 and 1/3
//    (nodes C<k>), and the quadrangle in four quadrangles through two inner
//    nodes (L<k>) at the images of (-1/3, 0) and (1/3, 0), the slave edge
//    being the cell's local edge eta = -1;
//  - SEG3 on a TRIA6 or QUAD8: nothing changes (each segment is its patch).
// k is the new node's number (1-based index) in the new mesh. Groups of cells
// list the children in place of their parent (new cells get fresh names
// M<k>); groups of nodes are copied unchanged, as code_aster does.
#pragma once
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace aster::mesh {

struct LacPatches {
  Mesh mesh;
  // Per slave segment given (in order): the new-mesh cells of its patch.
  std::vector<std::vector<int>> patches;
};

// Throws aster::Error naming the cell when a slave cell is not a SEG2/SEG3,
// bounds no 2D cell, bounds a 2D cell of another type than the above, or when
// one 2D cell bears two slave segments.
LacPatches cutLacPatches(const Mesh& mesh, const std::vector<int>& slaveCells);

}  // namespace aster::mesh
