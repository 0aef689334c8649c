// gmsh meshes through the gmsh C++ API: .msh (2.2 and 4.1, ASCII or binary)
// and .geo scripts meshed on the fly. Physical groups become GROUP_MA (by name,
// "GM<tag>" when unnamed) plus GROUP_NO of their nodes. Cells and nodes are
// named M<tag> and N<tag>. Nodes are converted to code_aster's ordering.
//
// Cells in no group: the writer puts them in one physical group per dimension
// named kGmshUngroupedName, which the reader recognises: it keeps the cells of
// its entities (POI1 included) but makes no GROUP_MA of it. A POI1 cell in no
// group thus survives a round trip, while the points gmsh itself puts on every
// geometric vertex (0-D entities in no physical group) are still dropped; and
// no cell needs gmsh's Mesh.SaveAll, with which MSH 2.2 loses the physical
// groups of every element.
//
// MSH 2.2 has no element tags of its own: gmsh numbers the elements in the order
// it writes them (by dimension, entity and type), so cell names M<tag> survive a
// 2.2 round trip only for cells already in that order (4.1 keeps the tags); and
// it writes a cell of several groups once per group, copies the reader merges
// (same entity, type and nodes).
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/nodal_field.hpp"

namespace aster::mesh {

// Reserved physical group name of the cells in no group (not a code_aster group
// name: it holds a '-' and a ':').
inline constexpr const char* kGmshUngroupedName = "aster-lite:ungrouped";

struct GmshReadOptions {
  // ONELAB numbers set before the file is opened (e.g. {"N", 4} for ssnp150.geo).
  std::vector<std::pair<std::string, double>> numbers;
  // gmsh runs the commands of the scripts it opens, SystemCall included: only
  // with `scripts` is it handed a file gmshScriptRisk warns about.
  bool scripts = false;
};

// Why gmsh would run commands when it opens `path`, "" when it would only read
// a mesh: a .geo script; a file not ending in .msh (gmsh chooses by extension
// how to open a file, and makes a .py or .exe the program of a solver); a
// "<path>.opt" beside it, which gmsh merges as a script.
std::string gmshScriptRisk(const std::string& path);

// Kept: every cell of dimension >= 1, cells of dimension 0 only when they are in
// a physical group (gmsh puts one on every geometric point), nodes used by a kept cell.
// Without options.scripts, a file gmshScriptRisk warns about is refused. A file
// not ending in .geo is a mesh file: checkMshFile (msh_check.hpp) first
// reports a malformed file with its line and what was expected; a failure of gmsh
// itself then gives "<path>: gmsh error: <gmsh's message> (expected a gmsh .msh
// file, version 2.2 or 4.1)".
Mesh readGmshMesh(const std::string& path, const GmshReadOptions& options = {});

struct GmshWriteOptions {
  double version = 4.1;  // 2.2 or 4.1
  bool binary = false;
};

// Cell groups become physical groups, cells in no group go to the reserved one;
// node groups are not written (gmsh has no such thing: the reader rebuilds node
// groups from the cells).
void writeGmshMesh(const Mesh& mesh, const std::string& path, const GmshWriteOptions& options = {});

// The mesh followed by one NodeData view per field name, one step per instant.
// Version 2.2 ASCII is written by aster-lite itself, without libgmsh (msh2_writer.hpp).
// Fields of 2 components are padded to 3 (gmsh vectors); other counts than
// 1, 2, 3 or 9 are written as one scalar view per component ("SIEF_SIXX").
// Cell fields (ElementData, ElementNodeData views) in version 2.2 ASCII only.
void writeGmshResults(const Mesh& mesh, const std::string& path, const std::vector<FieldInstant>& instants,
                      const GmshWriteOptions& options = {});

}  // namespace aster::mesh
