// L2 norms and errors against values integrated by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "mesh/mesh.hpp"
#include "post/norms.hpp"

using namespace aster;

namespace {

// The unit square as two QUAD8 cells [0,0.5]x[0,1] and [0.5,1]x[0,1], or (tria)
// as four TRIA6 cells; values of f at the nodes, one component per function.
struct Square {
  mesh::Mesh mesh;
  std::vector<int> cells;
};

int node(mesh::Mesh& m, double x, double y) {
  for (int i = 0; i < m.nodeCount(); ++i)
    if ((m.node(i) - Eigen::Vector3d(x, y, 0)).norm() < 1e-12) return i;
  return m.addNode({x, y, 0});
}

Square quad8Square() {
  Square s;
  for (double x0 : {0.0, 0.5}) {
    const double x1 = x0 + 0.5, xm = x0 + 0.25;
    std::vector<int> n{node(s.mesh, x0, 0), node(s.mesh, x1, 0), node(s.mesh, x1, 1), node(s.mesh, x0, 1),
                       node(s.mesh, xm, 0), node(s.mesh, x1, 0.5), node(s.mesh, xm, 1), node(s.mesh, x0, 0.5)};
    s.cells.push_back(s.mesh.addCell(mesh::CellType::QUAD8, n));
  }
  return s;
}

Square tria6Square() {
  Square s;
  // Two triangles (0,0),(1,0),(1,1) and (0,0),(1,1),(0,1), counterclockwise.
  auto tri = [&](double ax, double ay, double bx, double by, double cx, double cy) {
    std::vector<int> n{node(s.mesh, ax, ay), node(s.mesh, bx, by), node(s.mesh, cx, cy),
                       node(s.mesh, (ax + bx) / 2, (ay + by) / 2), node(s.mesh, (bx + cx) / 2, (by + cy) / 2),
                       node(s.mesh, (cx + ax) / 2, (cy + ay) / 2)};
    s.cells.push_back(s.mesh.addCell(mesh::CellType::TRIA6, n));
  };
  tri(0, 0, 1, 0, 1, 1);
  tri(0, 0, 1, 1, 0, 1);
  return s;
}

std::vector<double> nodalValues(const mesh::Mesh& m, const std::vector<post::ExactFunction>& f) {
  std::vector<double> v;
  for (int i = 0; i < m.nodeCount(); ++i)
    for (const auto& g : f) v.push_back(g(m.node(i)(0), m.node(i)(1)));
  return v;
}

post::NodalValues all(const std::vector<double>& v, int components) {
  post::NodalValues nv;
  nv.values = &v;
  nv.componentCount = components;
  for (int c = 0; c < components; ++c) nv.components.push_back(c);
  return nv;
}

}  // namespace

TEST(L2Norms, Quad8ReproducesQuadraticFieldsExactly) {
  const Square s = quad8Square();
  const std::vector<post::ExactFunction> u{
      [](double x, double y) { return 1 + 2 * x - y + 3 * x * x - x * y + 0.5 * y * y; },
      [](double x, double y) { return x * x * y - 2 * x * y * y + 0.25; }};
  const auto v = nodalValues(s.mesh, u);
  const auto r = post::l2Norms(s.mesh, s.cells, all(v, 2), u);
  EXPECT_NEAR(r.error, 0.0, 1e-13);
  EXPECT_NEAR(r.measure, 1.0, 1e-14);
  EXPECT_NEAR(r.computed, r.exact, 1e-13);
}

TEST(L2Norms, PolynomialNormOnUnitSquareByHand) {
  // u = (x y, 1): int x^2 y^2 = 1/9, int 1 = 1.
  const Square s = quad8Square();
  const std::vector<post::ExactFunction> u{[](double x, double y) { return x * y; },
                                           [](double, double) { return 1.0; }};
  const auto v = nodalValues(s.mesh, u);
  auto nv = all(v, 2);
  EXPECT_NEAR(post::l2Norms(s.mesh, s.cells, nv).computed, std::sqrt(1.0 / 9.0 + 1.0), 1e-14);
  nv.components = {0};
  EXPECT_NEAR(post::l2Norms(s.mesh, s.cells, nv).computed, 1.0 / 3.0, 1e-14);
  // Weights: 4 (x y)^2 + 1: 4/9 + 1.
  nv.components = {0, 1};
  nv.weights = {4.0, 1.0};
  EXPECT_NEAR(post::l2Norms(s.mesh, s.cells, nv).computed, std::sqrt(4.0 / 9.0 + 1.0), 1e-14);
}

TEST(L2Norms, Tria6SquareOfXSquared) {
  // int_0^1 x^4 = 1/5.
  const Square s = tria6Square();
  const std::vector<post::ExactFunction> u{[](double x, double) { return x * x; }};
  const auto v = nodalValues(s.mesh, u);
  const auto r = post::l2Norms(s.mesh, s.cells, all(v, 1), u);
  EXPECT_NEAR(r.computed, std::sqrt(0.2), 1e-14);
  EXPECT_NEAR(r.error, 0.0, 1e-14);
}

TEST(L2Errors, ZeroFieldAgainstLinearExactSolution) {
  // u_h = 0, u = x: error = exact norm = sqrt(1/3).
  const Square s = quad8Square();
  const std::vector<double> v(s.mesh.nodeCount(), 0.0);
  const auto r = post::l2Norms(s.mesh, s.cells, all(v, 1), {[](double x, double) { return x; }});
  EXPECT_NEAR(r.error, std::sqrt(1.0 / 3.0), 1e-14);
  EXPECT_NEAR(r.exact, std::sqrt(1.0 / 3.0), 1e-14);
  EXPECT_NEAR(r.computed, 0.0, 1e-15);
}

namespace {
// Two SEG3 cells along the direction (0.6, 0.8), arc length s in [0, 2]; the
// vertex values are g(s) at s = 0, 1, 2, the mid nodes hold 99 (each test sets
// them).
struct Chain {
  mesh::Mesh mesh;
  std::vector<int> cells;
  std::vector<double> values;
};
Chain segChain(double (*g)(double)) {
  Chain c;
  auto at = [&](double s) { return c.mesh.addNode({0.6 * s, 0.8 * s, 0}); };
  const int a = at(0), b = at(1), d = at(2), m1 = at(0.5), m2 = at(1.5);
  c.cells.push_back(c.mesh.addCell(mesh::CellType::SEG3, {a, b, m1}));
  c.cells.push_back(c.mesh.addCell(mesh::CellType::SEG3, {b, d, m2}));
  c.values = {g(0), g(1), g(2), 99.0, 99.0};
  return c;
}
double arcLength(double x, double y) { return std::hypot(x, y); }
}  // namespace

// A LAGS_C linear along each SEG3 (INTERPOL_LAGS_C='LINEAIRE') shows the mean
// of its ends at the middle node: the shape functions then give that linear field.
TEST(L2Errors, Seg3WithMeanAtMiddleNodeIsLinear) {
  Chain c = segChain([](double s) { return 1 + 3 * s; });
  c.values[3] = 0.5 * (c.values[0] + c.values[1]);
  c.values[4] = 0.5 * (c.values[1] + c.values[2]);
  const auto r = post::l2Norms(c.mesh, c.cells, all(c.values, 1),
                               {[](double x, double y) { return 1 + 3 * arcLength(x, y); }});
  EXPECT_NEAR(r.error, 0.0, 1e-13);
  EXPECT_NEAR(r.measure, 2.0, 1e-14);
  // int_0^2 (1+3s)^2 ds = [(1+3s)^3/9]_0^2 = (343 - 1)/9 = 38.
  EXPECT_NEAR(r.exact, std::sqrt(38.0), 1e-12);
}

TEST(L2Errors, Seg3LinearDataAgainstQuadraticByHand) {
  // Vertex data of s^2: 0, 1, 4, means 0.5, 2.5 at the middle nodes: linear on
  // each cell. Error^2 on each cell: int_0^1 (t - t^2)^2 dt = 1/30, twice: 1/15.
  Chain c = segChain([](double s) { return s * s; });
  c.values[3] = 0.5;
  c.values[4] = 2.5;
  const auto r = post::l2Norms(c.mesh, c.cells, all(c.values, 1),
                               {[](double x, double y) { return x * x + y * y; }});
  EXPECT_NEAR(r.error, std::sqrt(1.0 / 15.0), 1e-13);
  // int_0^2 s^4 = 32/5.
  EXPECT_NEAR(r.exact, std::sqrt(32.0 / 5.0), 1e-12);
}

TEST(L2Errors, Seg3ShapeFunctionsReproduceQuadratic) {
  Chain c = segChain([](double s) { return s * s; });
  c.values[3] = 0.25;
  c.values[4] = 2.25;
  const auto r = post::l2Norms(c.mesh, c.cells, all(c.values, 1),
                               {[](double x, double y) { return x * x + y * y; }});
  EXPECT_NEAR(r.error, 0.0, 1e-13);
}

TEST(L2Norms, RejectsMixedDimensionsAndBadSizes) {
  Square s = quad8Square();
  const int seg = s.mesh.addCell(mesh::CellType::SEG2, {0, 1});
  const std::vector<double> v(s.mesh.nodeCount(), 1.0);
  EXPECT_THROW(post::l2Norms(s.mesh, {s.cells[0], seg}, all(v, 1)), Error);
  const std::vector<double> shortValues(3, 1.0);
  EXPECT_THROW(post::l2Norms(s.mesh, s.cells, all(shortValues, 1)), Error);
}
