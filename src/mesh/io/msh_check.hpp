// aster-lite's own check of a gmsh .msh file, made before the file is handed to
// gmsh: gmsh reports a malformed file only as "Error loading", this check says
// which line is wrong and what was expected. A binary file is checked in full:
// gmsh's binary readers trust every count, tag and size they read and crash on
// a damaged file. It does not build the mesh (gmsh does); it needs no gmsh library.
#pragma once
#include <optional>
#include <string>

#include "mesh/cell_type.hpp"

namespace aster::mesh {

// What aster-lite expects where a gmsh mesh file is read.
inline constexpr const char* kMshExpected = "a gmsh .msh file, version 2.2 or 4.1";

// Throws aster::Error "<path>:<line>: ..." (or "<path>: ..." for an empty file) when
//  - the first non-empty line is not $MeshFormat, or it is not at the very start
//    of the file (gmsh would read the file as a .geo script), or the next one is not
//    "<version> <file-type> <data-size>" with version 2.2, 4.0 or 4.1, file type
//    0 (ASCII) or 1 (binary) and data size 8;
//  - (ASCII) a $Section is not closed by its $EndSection (the line given is the
//    one of the section left open), an $EndSection closes another section or none;
//  - (ASCII 2.2) the counts after $Nodes / $Elements do not match the lines that
//    follow, a node line is not "<tag> <x> <y> <z>", an element line is not
//    "<tag> <type> <ntags> <tags> <nodes>", its type has no code_aster
//    equivalent, it has the wrong number of nodes or a node that $Nodes lacks;
//  - (ASCII 4.0 and 4.1) the same for the entity blocks of $Nodes and $Elements;
//  - (ASCII) $NodeData, $ElementData, $ElementNodeData: their tags, a time step
//    0 to 100000, entity lines of a tag defined before and its values;
//    $InterpolationScheme: matrices of the numbers that follow; (ASCII 4.x)
//    $Entities: as many lines as entities announced; $PartitionedEntities,
//    $Periodic, $GhostElements, $Parametrizations: refused (gmsh trusts their sizes);
//  - a $PhysicalNames line is not '<dimension> <tag> "<name>"' with dimension 0 to 3;
//  - (binary, "<path>: byte <offset> (binary section $<name> at byte <offset>): ...")
//    the file is not 4.1 or 2.2, the integer after the version line is not 1, a
//    section is not closed by "$End<name>" right after its content, a count is
//    larger than the rest of the file can hold or than the blocks it announces,
//    a node or element tag is 0 or defined twice, a coordinate is not finite, an
//    element type has no code_aster equivalent or is not of its entity's
//    dimension, an element refers to an undefined node or entity, or the file
//    has a section gmsh reads that aster-lite does not check ($Periodic,
//    $PartitionedEntities, $NodeData...: refused; unknown sections are skipped).
//  - the file is not framed as gmsh frames it: gmsh reads lines with fgets, in
//    pieces of at most 254 or 1022 bytes, and opens a section at every piece that
//    starts with '$' (comparing the beginning of the name: "$NodesX" is $Nodes).
//    Refused: a header line longer than 254 bytes, a '$' after the first byte of
//    a longer line, a name gmsh reads as another section, a second $MeshFormat
//    (gmsh reads the file type again), in $Comments a line "$<name>" of a section
//    gmsh reads; (binary) a section marker not alone on its chunk (a full
//    1023-byte chunk is not the end of the file), a chunk "<byte>End<name>"
//    inside a skipped section $<name> (gmsh ends it there).
// Text between sections is skipped, as gmsh does, and so are the other lines of $Comments.
// A section left open is reported before any error on the lines inside it (a
// truncated file reads as such, not as a bad last line).
void checkMshFile(const std::string& path);

// gmsh element type numbers of the code_aster cell types (TRIA7 has none).
std::optional<CellType> cellTypeOfGmshElement(int gmshElementType);
// Throws aster::Error for TRIA7.
int gmshElementType(CellType type);
// "15 (POI1), 1 (SEG2), 8 (SEG3), ..." for messages.
std::string supportedGmshElementTypes();

}  // namespace aster::mesh
