#include "mesh/cell_type.hpp"

#include <vector>

#include "core/error.hpp"
#include "core/suggest.hpp"

namespace aster::mesh {

namespace {

struct CellTypeInfo {
  std::string name;
  int nodes;
  int vertices;
  int dim;
};

const CellTypeInfo& info(CellType t) {
  static const CellTypeInfo table[kCellTypeCount] = {
      {"POI1", 1, 1, 0},      {"SEG2", 2, 2, 1},      {"SEG3", 3, 2, 1},      {"SEG4", 4, 2, 1},
      {"TRIA3", 3, 3, 2},     {"TRIA6", 6, 3, 2},     {"TRIA7", 7, 3, 2},     {"QUAD4", 4, 4, 2},
      {"QUAD8", 8, 4, 2},     {"QUAD9", 9, 4, 2},     {"TETRA4", 4, 4, 3},    {"TETRA10", 10, 4, 3},
      {"PENTA6", 6, 6, 3},    {"PENTA15", 15, 6, 3},  {"PENTA18", 18, 6, 3},  {"PYRAM5", 5, 5, 3},
      {"PYRAM13", 13, 5, 3},  {"HEXA8", 8, 8, 3},     {"HEXA20", 20, 8, 3},   {"HEXA27", 27, 8, 3}};
  return table[static_cast<int>(t)];
}

}  // namespace

const std::string& cellTypeName(CellType t) { return info(t).name; }

bool isCellTypeName(const std::string& name) {
  for (int i = 0; i < kCellTypeCount; ++i)
    if (info(static_cast<CellType>(i)).name == name) return true;
  return false;
}

CellType cellTypeFromName(const std::string& name) {
  std::vector<std::string> names;
  for (int i = 0; i < kCellTypeCount; ++i) {
    const auto t = static_cast<CellType>(i);
    if (info(t).name == name) return t;
    names.push_back(info(t).name);
  }
  const std::string hint = didYouMean(name, names);
  throw Error("unknown cell type '" + name + "'" + (hint.empty() ? "" : ";" + hint) + " (types: " +
              joinNames(names) + ")");
}

int nodeCount(CellType t) { return info(t).nodes; }
int vertexCount(CellType t) { return info(t).vertices; }
int topologicalDimension(CellType t) { return info(t).dim; }
bool isQuadratic(CellType t) { return info(t).nodes > info(t).vertices; }

}  // namespace aster::mesh
