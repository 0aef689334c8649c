// The code_aster cell types and what every module needs to know about them.
// Node ordering is code_aster's (vertices first, then mid-edge nodes, then face
// and volume centres); conversions to other conventions live in node_ordering.
#pragma once
#include <string>

namespace aster::mesh {

enum class CellType {
  POI1, SEG2, SEG3, SEG4,
  TRIA3, TRIA6, TRIA7, QUAD4, QUAD8, QUAD9,
  TETRA4, TETRA10, PENTA6, PENTA15, PENTA18, PYRAM5, PYRAM13, HEXA8, HEXA20, HEXA27
};

constexpr int kCellTypeCount = 20;
constexpr int kMaxCellNodes = 27;

const std::string& cellTypeName(CellType t);
// Throws aster::Error naming the unknown type (with a suggestion).
CellType cellTypeFromName(const std::string& name);
bool isCellTypeName(const std::string& name);

int nodeCount(CellType t);
int vertexCount(CellType t);
int topologicalDimension(CellType t);
// SEG3, TRIA6, QUAD8... : nodes beyond the vertices.
bool isQuadratic(CellType t);

}  // namespace aster::mesh
