// MODI_MAILLAGE ORIE_PEAU in 2D: boundary segments oriented so that their
// normal points out of the adjacent 2D cell. Convention: a segment from node a
// to node b (in the XY plane) has the normal (dy, -dx) / length, the outward
// normal when the boundary is walked counterclockwise.
#pragma once
#include <vector>

#include "mesh/mesh.hpp"

namespace aster::mesh {

// Reverses (in place) the segments (SEG2, SEG3, SEG4) of `cells` whose normal
// points into their adjacent 2D cell. A segment touching no 2D cell (a rigid
// master like SSNP150's MAITRE) is oriented along its chain, in the direction of
// the chain's first segment in `cells`. Returns how many were reversed.
// Throws for a non-segment cell or a segment shared by two 2D cells.
int orientBoundarySegments(Mesh& mesh, const std::vector<int>& cells);

// A segment of a load whose normal points into the 2D cell it bounds (AFFE_CHAR_MECA's
// VERI_NORM), with that cell.
struct InwardSegment {
  int segment;
  int cell;
};
// The segments of `cells` whose normal points into their only adjacent 2D cell, in
// the order of `cells`; nothing changes. Segments touching no 2D cell, or lying
// between two, have no outward side and are not judged; other cells are skipped.
std::vector<InwardSegment> inwardSegments(const Mesh& mesh, const std::vector<int>& cells);

// The segment's nodes in the reverse direction (SEG3: b, a, middle).
void reverseSegment(Mesh& mesh, int cell);

}  // namespace aster::mesh
