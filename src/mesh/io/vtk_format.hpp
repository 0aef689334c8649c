// VTK output for ParaView: .vtu (XML, ASCII) with nodal point data and cell data, and a .pvd
// collection listing one .vtu per instant.
#pragma once
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/nodal_field.hpp"

namespace aster::mesh {

// Point data named by field. Fields of 2 components are padded to 3 (ParaView
// vectors). A plane displacement with more components (DX, DY, LAGS_C) is the
// vector (DX, DY, 0) under the field's name and one scalar array per other
// component, named <field>_<component> (DEPL_LAGS_C): a multiplier is never
// drawn as a third displacement. A "cell type" cell array is not written.
// Cell fields (at Gauss points, ELGA, or at cell nodes, ELNO) are cell data:
// per cell the mean of the values at its points, one array per field named
// <field>_MEAN (SIEF_ELGA_MEAN) with a component per field component (SIXX,
// SIYY...), NaN on the cells the field does not cover.
void writeVtu(const Mesh& mesh, const std::string& path, const std::vector<NodalField>& fields = {},
              const std::vector<CellValues>& cellFields = {});

// Writes <stem>_<k>.vtu per instant next to `pvdPath` and the collection file.
void writePvd(const Mesh& mesh, const std::string& pvdPath, const std::vector<FieldInstant>& instants);

// The collection file alone: one data set per instant, files named relative to it.
struct PvdEntry {
  double time = 0.0;
  std::string file;
};
void writePvdCollection(const std::string& pvdPath, const std::vector<PvdEntry>& entries);

}  // namespace aster::mesh
