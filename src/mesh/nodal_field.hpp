// Fields handed to the result writers (MED, gmsh, VTK), grouped by instant:
// nodal fields (one row of components per mesh node) and cell fields (values at
// the Gauss points or at the nodes of some cells), as plain values.
#pragma once
#include <string>
#include <vector>

#include "mesh/cell_type.hpp"

namespace aster::mesh {

struct NodalField {
  std::string name;                     // e.g. "DEPL"
  std::vector<std::string> components;  // e.g. {"DX", "DY"}
  std::vector<double> values;           // nodeCount * components.size(), node-major
};

// The integration points of one cell type on its reference cell, as the MED
// format records them (a "localization"): the reference coordinates of the
// cell's nodes in code_aster's node order, those of the points, the weights.
struct GaussLocalization {
  CellType type = CellType::POI1;
  int dimension = 0;            // coordinates per point
  std::vector<double> nodes;    // nodeCount(type) * dimension
  std::vector<double> points;   // weights.size() * dimension
  std::vector<double> weights;
};

// Values on some cells (SIEF_ELGA, SIGM_ELNO...): for each cell of `cells`,
// points * components numbers, point after point, a point being a Gauss point
// (atNodes false: `localizations` gives one per cell type present) or a node
// of the cell in the cell's node order (atNodes true).
struct CellValues {
  std::string name;
  std::vector<std::string> components;
  std::vector<int> cells;
  std::vector<int> offsets;  // into values, per cell, size cells.size()+1
  std::vector<double> values;
  bool atNodes = false;
  std::vector<GaussLocalization> localizations;
};

struct FieldInstant {
  int index = 0;      // NUME_ORDRE
  double time = 0.0;  // INST
  std::vector<NodalField> fields;
  std::vector<CellValues> cellFields = {};
};

}  // namespace aster::mesh

namespace aster::mesh {

class Mesh;

// The mean of component c over the points of field.cells[k]: the one value per
// cell that the VTK and gmsh writers give a field at Gauss points.
inline double pointMean(const CellValues& f, std::size_t k, std::size_t c) {
  const std::size_t nc = f.components.size();
  const std::size_t begin = static_cast<std::size_t>(f.offsets[k]), end = static_cast<std::size_t>(f.offsets[k + 1]);
  const std::size_t points = nc ? (end - begin) / nc : 0;
  double sum = 0;
  for (std::size_t p = 0; p < points; ++p) sum += f.values[begin + p * nc + c];
  return points ? sum / static_cast<double>(points) : 0.0;
}

// Checks the sizes of a cell field against the mesh (throws aster::Error naming `writer`).
void checkCellValues(const Mesh& mesh, const CellValues& f, const std::string& writer);

}  // namespace aster::mesh
