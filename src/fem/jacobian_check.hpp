// The sign of the Jacobian of a mesh cell's isoparametric map where its
// elements integrate: what AFFE_MODELE's VERI_JACOBIEN checks.
#pragma once
#include "mesh/mesh.hpp"

namespace aster::fem {

// At the points of the rule the elements integrate with (fullSurfaceRule,
// fullEdgeRule): how many have det(dx/dxi) > 0, < 0 and = 0 for a 2D cell in
// the XY plane, |dx/dxi| > 0 and = 0 for a segment. A cell of another type
// (POI1, 3D, SEG4, TRIA7) has no point: all counts are 0.
struct JacobianSigns {
  int positive = 0, negative = 0, zero = 0;
  double smallest = 0;  // the determinant (the length ratio) nearest to zero or below
};
// `axisymmetric`: the cell is in an AXIS model (its TRIA6 rule differs).
JacobianSigns jacobianSigns(const mesh::Mesh& mesh, int cell, bool axisymmetric);

}  // namespace aster::fem
