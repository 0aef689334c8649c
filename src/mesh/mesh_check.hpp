// Checks of a mesh after reading (LIRE_MAILLAGE): coordinates always,
// VERI_MAIL's checks on demand.
#pragma once
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace aster::mesh {

// Throws aster::Error naming the first node with a NaN or infinite coordinate.
void checkFiniteCoordinates(const Mesh& mesh);

// What VERI_MAIL finds, as code_aster's LIRE_MAILLAGE does: each entry is a
// message naming the nodes or cells at fault (at most a few, then a count).
struct MeshDefects {
  // Orphan nodes (in no cell); cells with the same nodes as another; cells
  // whose smallest distance between two of their nodes is below `flatness`
  // times the largest (flattened, or with coincident nodes).
  std::vector<std::string> alarms;
  // Cells with a node twice in their connectivity: no element can be built on them.
  std::string fatal;
};
MeshDefects findDefects(const Mesh& mesh, double flatness);

// "M4 (QUAD4 of SURFACE)": a cell as messages name it, with its groups of cells.
std::string describeCell(const Mesh& mesh, int cell, const std::vector<std::vector<int>>& groupsOfCells);

}  // namespace aster::mesh
