// Nodal fields handed to the result writers (MED, gmsh, VTK): plain values, one
// row of components per mesh node, grouped by instant.
#pragma once
#include <string>
#include <vector>

namespace aster::mesh {

struct NodalField {
  std::string name;                     // e.g. "DEPL"
  std::vector<std::string> components;  // e.g. {"DX", "DY"}
  std::vector<double> values;           // nodeCount * components.size(), node-major
};

struct FieldInstant {
  int index = 0;      // NUME_ORDRE
  double time = 0.0;  // INST
  std::vector<NodalField> fields;
};

}  // namespace aster::mesh
