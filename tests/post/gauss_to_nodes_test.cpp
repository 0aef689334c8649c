// ELGA -> ELNO extrapolation (post::gaussToNodesMatrix): on every surface cell, a
// field that the vertex element reproduces (a constant on TRIA3 with its one
// point; linear on TRIA6; bilinear on QUAD4, QUAD8, QUAD9) is recovered exactly
// at every node, mid-side and centre nodes included; and the QUAD4 2x2 matrix
// equals its closed form (the inverse of the bilinear shape functions at
// +-1/sqrt(3): 1 + sqrt(3)/2 at the nearest point, -1/2 at the two neighbours,
// 1 - sqrt(3)/2 at the opposite one).
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "fem/quadrature.hpp"
#include "fem/shape_functions.hpp"
#include "post/gauss_to_nodes.hpp"

using namespace aster;
using fem::CellType;

namespace {

template <CellType T>
Eigen::MatrixXd referenceNodes() {
  return fem::Cell<T>::referenceNodes();
}

Eigen::MatrixXd nodesOf(CellType t) {
  switch (t) {
    case CellType::TRIA3: return referenceNodes<CellType::TRIA3>();
    case CellType::TRIA6: return referenceNodes<CellType::TRIA6>();
    case CellType::QUAD4: return referenceNodes<CellType::QUAD4>();
    case CellType::QUAD8: return referenceNodes<CellType::QUAD8>();
    default: return referenceNodes<CellType::QUAD9>();
  }
}

// Two components: a + b xi + c eta + d xi eta (d = 0 on triangles), and another such.
double field(int c, bool triangle, const Eigen::Vector2d& p) {
  const double x = p(0), y = p(1);
  if (c == 0) return 1.5 - 2.25 * x + 0.75 * y + (triangle ? 0.0 : 0.625 * x * y);
  return -3.0 + 0.5 * x - 4.0 * y + (triangle ? 0.0 : -1.125 * x * y);
}

void checkExact(CellType t, bool constantOnly, bool axisymmetric) {
  const auto& rule = fem::fullSurfaceRule(t, axisymmetric);
  const Eigen::MatrixXd& G = post::modelGaussToNodes(t, axisymmetric);
  const bool triangle = t == CellType::TRIA3 || t == CellType::TRIA6;
  ASSERT_EQ(G.rows(), fem::cellNodeCount(t));
  ASSERT_EQ(G.cols(), rule.size());
  std::vector<double> in(2 * rule.size()), out(2 * G.rows());
  for (int q = 0; q < rule.size(); ++q)
    for (int c = 0; c < 2; ++c)
      in[2 * q + c] = constantOnly ? (c ? -3.0 : 1.5) : field(c, triangle, rule.points[q]);
  post::extrapolateToNodes(G, in.data(), 2, out.data());
  const Eigen::MatrixXd X = nodesOf(t);
  for (int a = 0; a < G.rows(); ++a)
    for (int c = 0; c < 2; ++c) {
      const double exact = constantOnly ? (c ? -3.0 : 1.5) : field(c, triangle, X.row(a).transpose());
      EXPECT_NEAR(out[2 * a + c], exact, 1e-12) << fem::cellName(t) << " node " << a + 1 << " component " << c;
    }
}

}  // namespace

// Each in plane (D_PLAN, C_PLAN) and AXIS models (TRIA6: FPG3, FPG6).
TEST(GaussToNodes, Tria3OnePointGivesItsValueToEveryNode) {
  for (bool axis : {false, true}) checkExact(CellType::TRIA3, true, axis);
}
TEST(GaussToNodes, Tria6LinearFieldIsExact) {
  for (bool axis : {false, true}) checkExact(CellType::TRIA6, false, axis);
}
TEST(GaussToNodes, Quad4BilinearFieldIsExact) {
  for (bool axis : {false, true}) checkExact(CellType::QUAD4, false, axis);
}
TEST(GaussToNodes, Quad8BilinearFieldIsExact) {
  for (bool axis : {false, true}) checkExact(CellType::QUAD8, false, axis);
}
TEST(GaussToNodes, Quad9BilinearFieldIsExact) {
  for (bool axis : {false, true}) checkExact(CellType::QUAD9, false, axis);
}

TEST(GaussToNodes, Tria6Fpg3MatrixHasItsClosedForm) {
  // The P1 functions at the FPG3 points are 2/3 at the nearest vertex and 1/6 at the
  // others; the inverse of that matrix: 5/3 on the diagonal, -1/3 elsewhere.
  const Eigen::MatrixXd& G = post::modelGaussToNodes(CellType::TRIA6, false);
  for (int a = 0; a < 3; ++a)
    for (int q = 0; q < 3; ++q) EXPECT_NEAR(G(a, q), a == q ? 5.0 / 3 : -1.0 / 3, 1e-14) << a << "," << q;
}

TEST(GaussToNodes, Quad4MatrixHasItsClosedForm) {
  const double g = 1 / std::sqrt(3.0);
  // Points in code_aster's FPG4 order (counterclockwise), so point k is nearest node k.
  const std::vector<Eigen::Vector2d> pts{{-g, -g}, {g, -g}, {g, g}, {-g, g}};
  const Eigen::MatrixXd G = post::gaussToNodesMatrix(CellType::QUAD4, pts);
  const double near = 1 + std::sqrt(3.0) / 2, far = 1 - std::sqrt(3.0) / 2;
  for (int a = 0; a < 4; ++a)
    for (int q = 0; q < 4; ++q) {
      const int d = (q - a + 4) % 4;
      const double expected = d == 0 ? near : d == 2 ? far : -0.5;
      EXPECT_NEAR(G(a, q), expected, 1e-13) << a << "," << q;
    }
}

TEST(GaussToNodes, TooFewPointsAreRefused) {
  const std::vector<Eigen::Vector2d> pts{{0.1, 0.1}, {0.5, 0.2}};
  EXPECT_THROW(post::gaussToNodesMatrix(CellType::QUAD4, pts), Error);
  EXPECT_THROW(post::gaussToNodesMatrix(CellType::SEG2, pts), Error);
}

TEST(GaussToNodes, QuadraticFieldIsFittedByLeastSquaresNotInterpolated) {
  // eta^2 at the 3x3 points (eta = -sqrt(3/5), 0, sqrt(3/5), three points each): the
  // best bilinear fit is the constant mean 0.4 (the odd part is zero by symmetry), which
  // every node gets, where an interpolation through the 9 points would give 1 at the corners.
  for (CellType t : {CellType::QUAD8, CellType::QUAD9}) {
    const auto& rule = fem::fullSurfaceRule(t, false);
    std::vector<double> in(rule.size()), out(fem::cellNodeCount(t));
    for (int q = 0; q < rule.size(); ++q) in[q] = rule.points[q](1) * rule.points[q](1);
    post::extrapolateToNodes(post::modelGaussToNodes(t, false), in.data(), 1, out.data());
    for (double v : out) EXPECT_NEAR(v, 0.4, 1e-13) << fem::cellName(t);
  }
}
