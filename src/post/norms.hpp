// L2 norms and L2 errors of nodal fields, integrated with the cells' shape
// functions and Gauss rules (POST_ELEM NORME, POST_ERREUR).
//   Surface cells (TRIA3..QUAD9): the field is interpolated with the cell's
//   shape functions, integrated with a rule exact to degree 2p+2 or more.
//   Edge cells (SEG2, SEG3): with the cell's shape functions too, integrated
//   along the cell's length in the mesh's (undeformed) geometry. (A LAGS_C
//   linear along a SEG3 shows the mean of its ends at the middle node, so
//   this interpolation gives that linear pressure.)
// Values are node-major: values[node * componentCount + c].
#pragma once
#include <functional>
#include <vector>

#include "mesh/mesh.hpp"

namespace aster::post {

// An exact solution component as a function of (x, y).
using ExactFunction = std::function<double(double x, double y)>;

struct NodalValues {
  const std::vector<double>* values = nullptr;
  int componentCount = 0;
  std::vector<int> components;  // indices taken into the norm
  std::vector<double> weights;  // per taken component (empty: all 1): sum w_c u_c^2
};

struct L2Result {
  double error = 0;     // ||u_h - u||  (u = 0 when no exact function is given)
  double exact = 0;     // ||u||
  double computed = 0;  // ||u_h||
  double measure = 0;   // area (or length) integrated over
};

// Over `cells` (surface or edge cells of `mesh`, mixed not allowed), the L2 norms
// of the field, of the exact solution (one function per taken component, or
// none: then error == computed) and of their difference.
L2Result l2Norms(const mesh::Mesh& mesh, const std::vector<int>& cells, const NodalValues& field,
                 const std::vector<ExactFunction>& exact = {});

// The integration points of the model on one cell, those the mechanics
// integrates with and fields at Gauss points (ELGA) live on: the full rule of
// surface cells (fem::fullSurfaceRule, code_aster's families and point order:
// TRIA3 1 point, TRIA6 3 (6 in AXIS), QUAD4 4, QUAD8 and QUAD9 9) and the
// segment's own rule on edge cells (fem::fullEdgeRule: SEG2 2 points, SEG3 4).
// `axisymmetric`: the model is AXIS.
struct CellGaussPoints {
  int count = 0;                 // points
  int nodes = 0;                 // nodes of the cell
  int dimension = 0;             // 2 surface, 1 edge
  std::vector<double> weights;   // per point: weight * |J| (area, or length, element)
  std::vector<double> shape;     // shape[q * nodes + a] = N_a at point q
  std::vector<double> xyz;       // per point: x, y, z (interpolated from the nodes)
};
CellGaussPoints modelGaussPoints(const mesh::Mesh& mesh, int cell, bool axisymmetric);
// The number of those points on a cell of this type (throws for other types).
int modelGaussPointCount(mesh::CellType type, bool axisymmetric);

}  // namespace aster::post
