// gmsh meshes through the gmsh C++ API: .msh (2.2 and 4.1, ASCII or binary)
// and .geo scripts meshed on the fly. Physical groups become GROUP_MA (by name,
// "GM<tag>" when unnamed) plus GROUP_NO of their nodes. Cells and nodes are
// named M<tag> and N<tag>. Nodes are converted to code_aster's ordering.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/nodal_field.hpp"

namespace aster::mesh {

struct GmshReadOptions {
  // ONELAB numbers set before the file is opened (e.g. {"N", 4} for ssnp150.geo).
  std::vector<std::pair<std::string, double>> numbers;
};

// Kept: every cell of dimension >= 1, cells of dimension 0 only when they are in
// a physical group (gmsh puts one on every geometric point), nodes used by a kept cell.
Mesh readGmshMesh(const std::string& path, const GmshReadOptions& options = {});

struct GmshWriteOptions {
  double version = 4.1;  // 2.2 or 4.1
  bool binary = false;
};

// Cell groups become physical groups; node groups are not written (gmsh has no
// such thing: the reader rebuilds node groups from the cells).
void writeGmshMesh(const Mesh& mesh, const std::string& path, const GmshWriteOptions& options = {});

// The mesh followed by one NodeData view per field name, one step per instant.
// Fields of 2 components are padded to 3 (gmsh vectors); other counts than
// 1, 2, 3 or 9 are written as one scalar view per component ("SIEF_SIXX").
void writeGmshResults(const Mesh& mesh, const std::string& path, const std::vector<FieldInstant>& instants,
                      const GmshWriteOptions& options = {});

}  // namespace aster::mesh
