// MED files (libmedc 4.1): unstructured meshes with families turned into groups
// (cell families -> GROUP_MA, node families -> GROUP_NO) and result fields:
// nodal, at Gauss points, at cell nodes.
// Connectivities are converted with code_aster's MED <-> code_aster node tables.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/nodal_field.hpp"

namespace aster::mesh {

// Reads the mesh called `meshName` (the first mesh of the file when empty).
// Errors name the file and what was expected: "<path>: not a MED file (no HDF5
// signature): expected a MED file written by Salome, code_aster or aster-lite"
// (checked before the MED library opens it, also by readMedNodalField), "<path>:
// the MED file holds no mesh (...)", "<path>: no mesh called 'X' in the MED file
// (expected one of the meshes present: A, B)", and the mesh of a failing MED call.
// The MED library reads the file in a child process: a damaged file that crashes
// HDF5 gives "<path>: the MED library (HDF5) crashed reading the file (signal
// SIGSEGV): a damaged MED file (...)". Counts the file announces beyond what it
// can hold or inconsistent with each other, node indices out of range, family
// numbers without their family, empty names, non-finite coordinates, cell types
// aster-lite does not read and a mesh without cells are errors.
Mesh readMedMesh(const std::string& path, const std::string& meshName = "");

// Writes the mesh (and groups, names when they fit in 16 characters) to a new file.
void writeMedMesh(const Mesh& mesh, const std::string& path, const std::string& meshName = "MAIL");

// The mesh followed by the fields, one MED time step per instant (numdt = index, dt =
// time): nodal fields on MED_NODE; cell fields as code_aster writes them, at Gauss
// points on MED_CELL with a localization per cell type (<elrefe>_____RIGI:
// QU4_____RIGI), at cell nodes on MED_NODE_ELEMENT, with a profile
// (<field>_<TYPE>) when they cover some of the cells of a type.
void writeMedResults(const Mesh& mesh, const std::string& path, const std::vector<FieldInstant>& instants,
                     const std::string& meshName = "MAIL");

// Adds to a MED file written by writeMedResults (as code_aster adds to the file of
// one unit): the mesh `meshName` unless `meshPresent` (the file holds it already),
// then the fields, whose names must not be in the file yet.
void addMedResults(const Mesh& mesh, const std::string& path, const std::vector<FieldInstant>& instants,
                   const std::string& meshName, bool meshPresent);

// One nodal field at one time step (numdt) as written above: components and values
// (read in a child process as readMedMesh).
NodalField readMedNodalField(const std::string& path, const std::string& fieldName, int numdt);

namespace detail {
// The readers' child process: runs `read` in it and returns what it returned, or
// throws the aster::Error it threw, or an error naming `path` when it died
// (signal, or an exit without a result). Declared here for its tests.
std::string readInChild(const std::string& path, const std::function<std::string()>& read);
}  // namespace detail

}  // namespace aster::mesh
