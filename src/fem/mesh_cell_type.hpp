// The reference cell of a mesh cell: the mesh knows every code_aster cell type,
// fem only the 1D and 2D cells that carry shape functions here.
#pragma once
#include <string>

#include "core/error.hpp"
#include "fem/cell_type.hpp"
#include "mesh/cell_type.hpp"

namespace aster::fem {

// Throws aster::Error naming `use` ("L2 norms", "a plane load") for other types.
inline CellType referenceCell(mesh::CellType t, const char* use) {
  switch (t) {
    case mesh::CellType::SEG2: return CellType::SEG2;
    case mesh::CellType::SEG3: return CellType::SEG3;
    case mesh::CellType::TRIA3: return CellType::TRIA3;
    case mesh::CellType::TRIA6: return CellType::TRIA6;
    case mesh::CellType::QUAD4: return CellType::QUAD4;
    case mesh::CellType::QUAD8: return CellType::QUAD8;
    case mesh::CellType::QUAD9: return CellType::QUAD9;
    default: break;
  }
  throw Error(std::string(use) + ": a " + mesh::cellTypeName(t) +
              " cell is not available (SEG2, SEG3, TRIA3, TRIA6, QUAD4, QUAD8, QUAD9 are)");
}

}  // namespace aster::fem
