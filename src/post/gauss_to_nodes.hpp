// Values at the nodes of a cell from values at its Gauss points (ELGA -> ELNO),
// by code_aster's construction of its Gauss-to-nodes matrix (MGANO):
// - one Gauss point: the value is given to every node;
// - otherwise the vertex nodes get the least-squares fit, at the Gauss points,
//   of the linear (vertex) element's shape functions (TRIA3 for TRIA3/TRIA6,
//   QUAD4 for QUAD4/QUAD8/QUAD9): P = M^-1 [N(g_1) ... N(g_npg)] with
//   M = sum_g N(g) N(g)^T, the plain inverse when there are as many points as
//   vertices; mid-side nodes get the mean of their edge's two vertices, the
//   QUAD9 centre the mean of the four.
// A field linear (TRIA) or bilinear (QUAD) in the reference coordinates is thus
// extrapolated exactly; the matrix depends only on the points, not on their order.
#pragma once
#include <vector>

#include <Eigen/Core>

#include "fem/cell_type.hpp"

namespace aster::post {

// The (nodes x points) matrix: value at node a = sum_q G(a, q) * value at point q.
// `points`: reference coordinates of the Gauss points. Throws aster::Error for an
// edge cell or when the points cannot determine the vertex fit.
Eigen::MatrixXd gaussToNodesMatrix(fem::CellType type, const std::vector<Eigen::Vector2d>& points);

// The matrix for the model's integration points (fem::fullSurfaceRule; AXIS when
// `axisymmetric`), built once per type.
const Eigen::MatrixXd& modelGaussToNodes(fem::CellType type, bool axisymmetric);

// out[a * components + c] = sum_q G(a, q) in[q * components + c].
void extrapolateToNodes(const Eigen::MatrixXd& G, const double* in, int components, double* out);

}  // namespace aster::post
