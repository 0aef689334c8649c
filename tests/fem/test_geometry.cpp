// Isoparametric map, Jacobian and its inverse; edge frames (normal convention,
// curvature of a SEG3 parabola against the closed form).
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "fem/edge_geometry.hpp"
#include "fem/isoparametric.hpp"

using namespace aster::fem;

TEST(Isoparametric, AffineQuad4AndInverse) {
  // The image of [-1,1]^2 under x = A xi + b.
  Eigen::Matrix2d A;
  A << 2.0, 0.5, -0.3, 1.5;
  const Eigen::Vector2d b(1, 2);
  NodeCoords<CellType::QUAD4> X;
  const auto R = Cell<CellType::QUAD4>::referenceNodes();
  for (int a = 0; a < 4; ++a) X.row(a) = (A * R.row(a).transpose() + b).transpose();
  const Eigen::Vector2d xi(0.3, -0.4);
  const auto j = jacobian<CellType::QUAD4>(X, Cell<CellType::QUAD4>::gradients(xi));
  EXPECT_NEAR((j.J - A).norm(), 0, 1e-14);
  EXPECT_NEAR(j.det, A.determinant(), 1e-14);
  EXPECT_NEAR((j.inverse * A - Eigen::Matrix2d::Identity()).norm(), 0, 1e-14);
  const Eigen::Vector2d x = mapPoint<CellType::QUAD4>(X, xi);
  EXPECT_NEAR((x - (A * xi + b)).norm(), 0, 1e-14);
  EXPECT_NEAR((inverseMap<CellType::QUAD4>(X, x) - xi).norm(), 0, 1e-12);
}

TEST(Isoparametric, CurvedQuad8InverseMapAndClockwiseError) {
  NodeCoords<CellType::QUAD8> X;
  X << 0, 0, 2, 0, 2.2, 1.8, 0, 2, 1, -0.2, 2.2, 1, 1, 2.1, 0.1, 1;
  const Eigen::Vector2d xi(-0.55, 0.7);
  const Eigen::Vector2d x = mapPoint<CellType::QUAD8>(X, xi);
  EXPECT_NEAR((inverseMap<CellType::QUAD8>(X, x) - xi).norm(), 0, 1e-12);
  // Physical gradients: grad_x of the interpolant of f = x is (1, 0).
  const auto G = Cell<CellType::QUAD8>::gradients(xi);
  const auto dN = physicalGradients<CellType::QUAD8>(G, jacobian<CellType::QUAD8>(X, G));
  EXPECT_NEAR((X.transpose() * dN - Eigen::Matrix2d::Identity()).norm(), 0, 1e-13);
  // Clockwise numbering is refused.
  NodeCoords<CellType::TRIA3> T;
  T << 0, 0, 0, 1, 1, 0;
  EXPECT_THROW(jacobian<CellType::TRIA3>(T, Cell<CellType::TRIA3>::gradients(Eigen::Vector2d(0.2, 0.2))),
               aster::Error);
}

TEST(EdgeGeometry, Seg2NormalConvention) {
  EdgeCoords<CellType::SEG2> X;
  X << 0, 0, 3, 4;
  const auto f = edgeFrame<CellType::SEG2>(X, 0.2);
  EXPECT_NEAR(f.jacobian, 2.5, 1e-15);  // half the length
  EXPECT_NEAR((f.normal - Eigen::Vector2d(0.8, -0.6)).norm(), 0, 1e-15);
  EXPECT_NEAR((f.point - Eigen::Vector2d(1.8, 2.4)).norm(), 0, 1e-15);
  EXPECT_EQ(f.curvature, 0.0);
  // Bottom edge of the unit square walked counterclockwise: outward normal (0,-1).
  X << 0, 0, 1, 0;
  EXPECT_NEAR((edgeFrame<CellType::SEG2>(X, 0).normal - Eigen::Vector2d(0, -1)).norm(), 0, 1e-15);
}

// SSNP150's master: the SEG3 (1.5,-0.05), (-0.5,-0.05), middle (0.5,0) is the
// parabola y = -0.05 (x-0.5)^2 walked from right to left.
TEST(EdgeGeometry, Seg3ParabolaCurvature) {
  EdgeCoords<CellType::SEG3> X;
  X << 1.5, -0.05, -0.5, -0.05, 0.5, 0.0;
  for (double xi : {-0.8, -0.1, 0.0, 0.45, 1.0}) {
    const auto f = edgeFrame<CellType::SEG3>(X, xi);
    const double x = f.point(0);
    EXPECT_NEAR(x, 0.5 - xi, 1e-15);  // x runs linearly from 1.5 to -0.5
    EXPECT_NEAR(f.point(1), -0.05 * (x - 0.5) * (x - 0.5), 1e-15);
    // Closed form: y' = -0.1 (x - 0.5), y'' = -0.1; kappa of the graph = y''/(1+y'^2)^1.5
    // when walked with increasing x; walking backwards flips the sign.
    const double yp = -0.1 * (x - 0.5);
    const double kappaGraph = -0.1 / std::pow(1 + yp * yp, 1.5);
    EXPECT_NEAR(f.curvature, -kappaGraph, 1e-14);
    // Normal (dy, -dx)/|.| with dx/dxi = -1, dy/dxi = -yp: points up (towards the body above).
    const Eigen::Vector2d n = Eigen::Vector2d(-yp, 1.0).normalized();
    EXPECT_NEAR((f.normal - n).norm(), 0, 1e-14);
    // dn/dxi and dt/dxi against central differences.
    const double h = 1e-5;
    const auto fp = edgeFrame<CellType::SEG3>(X, xi + h), fm = edgeFrame<CellType::SEG3>(X, xi - h);
    EXPECT_NEAR(((fp.normal - fm.normal) / (2 * h) - f.dNormal).norm(), 0, 1e-9);
    EXPECT_NEAR(((fp.tangent - fm.tangent) / (2 * h) - f.dTangent).norm(), 0, 1e-9);
  }
}
