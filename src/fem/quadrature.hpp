// Quadrature rules on the reference cells. Rules are built once and cached:
// the accessors return references to immutable tables, so element loops never
// allocate.
#pragma once
#include <vector>

#include <Eigen/Core>

#include "fem/cell_type.hpp"

namespace aster::fem {

template <int Dim>
struct QuadratureRule {
  using Point = Eigen::Matrix<double, Dim, 1>;
  std::vector<Point> points;   // on the reference cell
  std::vector<double> weights;  // sum = measure of the reference cell
  int degree = 0;               // polynomials up to this degree are integrated exactly
  int size() const { return static_cast<int>(weights.size()); }
};

// Gauss-Legendre on [-1,1], 1..kMaxGaussPoints points (exact to degree 2n-1).
inline constexpr int kMaxGaussPoints = 12;
const QuadratureRule<1>& gaussLegendre(int points);

// Tensor-product Gauss rule on [-1,1]^2 with n points per direction.
const QuadratureRule<2>& gaussQuadrangle(int pointsPerDirection);

// Symmetric rules with positive weights on the triangle (0,0),(1,0),(0,1),
// exact to the given degree (1..kMaxTriangleDegree): 1, 3, 6, 6, 7, 12 points
// (centroid; edge-interior 3-point; Dunavant 6-point degree 4; Radon 7-point
// degree 5; Dunavant 12-point degree 6).
inline constexpr int kMaxTriangleDegree = 6;
const QuadratureRule<2>& gaussTriangle(int degree);

// A rule exact to at least `degree` on the reference cell of a surface cell type.
const QuadratureRule<2>& surfaceRule(CellType t, int degree);
// A rule exact to at least `degree` on [-1,1].
const QuadratureRule<1>& edgeRule(int degree);

// Full integration of the stiffness of an undistorted cell, as code_aster's
// mechanics does: TRIA3 1 point, TRIA6 6 points (degree 4), QUAD4 2x2,
// QUAD8 and QUAD9 3x3; SEG2 2 points, SEG3 3 points.
const QuadratureRule<2>& fullSurfaceRule(CellType t);
const QuadratureRule<1>& fullEdgeRule(CellType t);

}  // namespace aster::fem
