// gmsh's MSH 2.2 ASCII format written by aster-lite itself, without libgmsh:
// loading libgmsh and its ~120 libraries took 0.2 s, more than the SSNP150 studies
// spend computing. writeGmshResults (gmsh_format.hpp) calls it for version 2.2 ASCII.
//
// What gmsh itself writes, except where noted:
//  - one discrete entity per (dimension, set of cell groups), numbered from 1 in the
//    order of the cells; one physical group per cell group and dimension, numbered
//    from 1 in the order of the groups, then the reserved kGmshUngroupedName per
//    dimension for the cells in no group;
//  - a cell in several groups is written once per group (MSH 2.2 gives an element one
//    physical group); the reader merges the copies. Element tags: the cell's number
//    (c + 1) for its first group, so that cell names M<tag> survive a round trip (gmsh
//    numbers elements in the order it writes them), and numbers after the last cell for
//    the other copies;
//  - the mesh once, then each field as a $NodeData view, one block per instant (gmsh
//    writes the mesh again before its views, and an $InterpolationScheme that only its
//    own adaptive views use);
//  - cell fields after the nodal ones: at Gauss points as $ElementData, the mean of
//    the cell's points per cell, named <field>_MEAN (SIEF_ELGA_MEAN); at cell nodes
//    as $ElementNodeData (SIGM_ELNO), in gmsh's node order; split into scalar
//    views as nodal fields (SIEF_ELGA_MEAN_SIXX);
//  - numbers with 17 significant digits (gmsh: 16), so that a round trip is exact.
#pragma once
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/nodal_field.hpp"

namespace aster::mesh {

// Fields as writeGmshResults: 2 components padded to 3, 1, 3 or 9 as they are, other
// counts one scalar view per component ("SIEF_SIXX"). The fields are checked by the caller.
void writeMsh2(const Mesh& mesh, const std::string& path, const std::vector<FieldInstant>& instants);

}  // namespace aster::mesh
