#include "post/gauss_to_nodes.hpp"

#include <array>
#include <string>

#include <Eigen/LU>

#include "core/error.hpp"
#include "fem/quadrature.hpp"
#include "fem/shape_functions.hpp"

namespace aster::post {
namespace {

// The shape functions of the vertex element at a reference point.
Eigen::VectorXd vertexShape(bool triangle, const Eigen::Vector2d& p) {
  if (triangle) return fem::Cell<fem::CellType::TRIA3>::values(p);
  return fem::Cell<fem::CellType::QUAD4>::values(p);
}

// Mid-side nodes: the two vertices of their edge (code_aster's node order).
constexpr int kTria6Edges[3][2] = {{0, 1}, {1, 2}, {2, 0}};
constexpr int kQuadEdges[4][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};

}  // namespace

Eigen::MatrixXd gaussToNodesMatrix(fem::CellType type, const std::vector<Eigen::Vector2d>& points) {
  if (fem::cellDimension(type) != 2)
    throw Error(std::string("values at the nodes of a ") + fem::cellName(type) +
                " cell: only surface cells (TRIA3, TRIA6, QUAD4, QUAD8, QUAD9) are extrapolated");
  const int nno = fem::cellNodeCount(type);
  const int npg = static_cast<int>(points.size());
  if (npg == 0) throw Error(std::string("extrapolation to the nodes of a ") + fem::cellName(type) + ": no Gauss point");
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(nno, npg);
  if (npg == 1) {
    G.setOnes();
    return G;
  }
  const bool triangle = type == fem::CellType::TRIA3 || type == fem::CellType::TRIA6;
  const int nnos = triangle ? 3 : 4;
  Eigen::MatrixXd F(nnos, npg);
  for (int q = 0; q < npg; ++q) F.col(q) = vertexShape(triangle, points[q]);
  const Eigen::MatrixXd M = F * F.transpose();
  Eigen::FullPivLU<Eigen::MatrixXd> lu(M);
  if (npg < nnos || !lu.isInvertible())
    throw Error(std::string("extrapolation to the nodes of a ") + fem::cellName(type) + ": " + std::to_string(npg) +
                " Gauss points do not determine the values at its " + std::to_string(nnos) + " vertices");
  const Eigen::MatrixXd P = lu.solve(F);  // nnos x npg
  G.topRows(nnos) = P;
  if (type == fem::CellType::TRIA6) {
    for (int e = 0; e < 3; ++e) G.row(3 + e) = 0.5 * (P.row(kTria6Edges[e][0]) + P.row(kTria6Edges[e][1]));
  } else if (type == fem::CellType::QUAD8 || type == fem::CellType::QUAD9) {
    for (int e = 0; e < 4; ++e) G.row(4 + e) = 0.5 * (P.row(kQuadEdges[e][0]) + P.row(kQuadEdges[e][1]));
    if (type == fem::CellType::QUAD9) G.row(8) = 0.25 * (P.row(0) + P.row(1) + P.row(2) + P.row(3));
  }
  return G;
}

const Eigen::MatrixXd& modelGaussToNodes(fem::CellType type, bool axisymmetric) {
  static const auto matrices = [] {
    std::array<std::array<Eigen::MatrixXd, 7>, 2> m;  // [axisymmetric][type]
    for (int axis = 0; axis < 2; ++axis)
      for (fem::CellType t : {fem::CellType::TRIA3, fem::CellType::TRIA6, fem::CellType::QUAD4, fem::CellType::QUAD8,
                              fem::CellType::QUAD9}) {
        const auto& rule = fem::fullSurfaceRule(t, axis == 1);
        std::vector<Eigen::Vector2d> points(rule.points.begin(), rule.points.end());
        m[axis][static_cast<int>(t)] = gaussToNodesMatrix(t, points);
      }
    return m;
  }();
  if (fem::cellDimension(type) != 2) gaussToNodesMatrix(type, {});  // throws with the message
  return matrices[axisymmetric ? 1 : 0][static_cast<int>(type)];
}

void extrapolateToNodes(const Eigen::MatrixXd& G, const double* in, int components, double* out) {
  const int nno = static_cast<int>(G.rows()), npg = static_cast<int>(G.cols());
  for (int a = 0; a < nno; ++a)
    for (int c = 0; c < components; ++c) {
      double s = 0;
      for (int q = 0; q < npg; ++q) s += G(a, q) * in[q * components + c];
      out[a * components + c] = s;
    }
}

}  // namespace aster::post
