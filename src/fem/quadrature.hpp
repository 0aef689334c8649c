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

// The integration points of code_aster's plane mechanical elements (the RIGI
// family of its element catalogue), with its coordinates, weights and point
// order, so that a point number k means the same point: TRIA3 FPG1 (centroid);
// TRIA6 FPG3 (interior points (1/6,1/6), (2/3,1/6), (1/6,2/3)), FPG6 in AXIS
// (Dunavant's degree 4); QUAD4 FPG4 (2x2, counterclockwise from (-,-)); QUAD8
// and QUAD9 FPG9 (3x3: corners, mid-edges, centre). Edge cells (fields at
// Gauss points, norms): SEG2 FPG2 (+1/sqrt3, -1/sqrt3), SEG3 FPG3 (-sqrt(3/5),
// 0, +sqrt(3/5)); code_aster's skin elements integrate SEG3 with FPG4, which
// would move SSNP150B's Gauss-point pressure rate (norms on its contact edge).
const QuadratureRule<2>& fullSurfaceRule(CellType t, bool axisymmetric);
const QuadratureRule<1>& fullEdgeRule(CellType t);

}  // namespace aster::fem
