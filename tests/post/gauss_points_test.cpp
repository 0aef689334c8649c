// The model's integration points on one cell (post::modelGaussPoints), against
// code_aster's families written by hand: FPG9 on quadrangles (corners
// counterclockwise, mid-edges, centre; +-sqrt(3/5), 0 with weights 5/9, 8/9) and
// FPG3 on SEG3 (-sqrt(3/5), 0, sqrt(3/5) with weights 5/9, 8/9, 5/9).
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "mesh/mesh.hpp"
#include "post/norms.hpp"

using namespace aster;

namespace {

const double a = std::sqrt(0.6);
// FPG9: (xi, eta, weight) in code_aster's order.
const double fpg9[9][3] = {{-a, -a, 25.0 / 81}, {a, -a, 25.0 / 81}, {a, a, 25.0 / 81}, {-a, a, 25.0 / 81},
                           {0, -a, 40.0 / 81},  {a, 0, 40.0 / 81},  {0, a, 40.0 / 81}, {-a, 0, 40.0 / 81},
                           {0, 0, 64.0 / 81}};
const double xi3[3] = {-a, 0.0, a};
const double w3[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};

}  // namespace

TEST(ModelGaussPoints, Quad8IsCodeAsterFpg9) {
  // The rectangle [1, 3] x [0, 0.5]: x = 2 + xi, y = 0.25 (1 + eta), |J| = 0.25.
  mesh::Mesh m;
  std::vector<int> n{m.addNode({1, 0, 0}), m.addNode({3, 0, 0}), m.addNode({3, 0.5, 0}), m.addNode({1, 0.5, 0}),
                     m.addNode({2, 0, 0}), m.addNode({3, 0.25, 0}), m.addNode({2, 0.5, 0}), m.addNode({1, 0.25, 0})};
  const int c = m.addCell(mesh::CellType::QUAD8, n);
  for (bool axis : {false, true}) {
    const auto g = post::modelGaussPoints(m, c, axis);
    ASSERT_EQ(g.count, 9);
    EXPECT_EQ(g.nodes, 8);
    EXPECT_EQ(g.dimension, 2);
    EXPECT_EQ(post::modelGaussPointCount(mesh::CellType::QUAD8, axis), 9);
    double area = 0;
    for (int q = 0; q < 9; ++q) {
      EXPECT_NEAR(g.xyz[3 * q], 2 + fpg9[q][0], 1e-15) << q;
      EXPECT_NEAR(g.xyz[3 * q + 1], 0.25 * (1 + fpg9[q][1]), 1e-15) << q;
      EXPECT_NEAR(g.weights[q], fpg9[q][2] * 0.25, 1e-15) << q;
      double sum = 0;
      for (int k = 0; k < 8; ++k) sum += g.shape[q * 8 + k];
      EXPECT_NEAR(sum, 1.0, 1e-15);
      area += g.weights[q];
    }
    EXPECT_NEAR(area, 1.0, 1e-14);
  }
}

TEST(ModelGaussPoints, CountsOfTheOtherCells) {
  for (bool axis : {false, true}) {
    EXPECT_EQ(post::modelGaussPointCount(mesh::CellType::TRIA3, axis), 1);
    EXPECT_EQ(post::modelGaussPointCount(mesh::CellType::TRIA6, axis), axis ? 6 : 3);  // FPG6 in AXIS, else FPG3
    EXPECT_EQ(post::modelGaussPointCount(mesh::CellType::QUAD4, axis), 4);
    EXPECT_EQ(post::modelGaussPointCount(mesh::CellType::QUAD9, axis), 9);
    EXPECT_EQ(post::modelGaussPointCount(mesh::CellType::SEG2, axis), 2);
    EXPECT_EQ(post::modelGaussPointCount(mesh::CellType::SEG3, axis), 3);
    EXPECT_THROW(post::modelGaussPointCount(mesh::CellType::POI1, axis), Error);
  }
}

TEST(ModelGaussPoints, Seg3WalkedBackwardsAndCurved) {
  // A straight SEG3 from (1, 0) to (0, 0): x = (1 - s) / 2, length element 1/2.
  mesh::Mesh m;
  const int s = m.addCell(mesh::CellType::SEG3, {m.addNode({1, 0, 0}), m.addNode({0, 0, 0}), m.addNode({0.5, 0, 0})});
  const auto g = post::modelGaussPoints(m, s, false);
  ASSERT_EQ(g.count, 3);
  EXPECT_EQ(g.dimension, 1);
  for (int q = 0; q < 3; ++q) {
    EXPECT_NEAR(g.xyz[3 * q], 0.5 * (1 - xi3[q]), 1e-15);
    EXPECT_NEAR(g.xyz[3 * q + 1], 0.0, 1e-15);
    EXPECT_NEAR(g.weights[q], 0.5 * w3[q], 1e-15);
  }
  // The parabola y = x (1 - x) from (0, 0) to (1, 0) through (0.5, 0.25): x = (1 + s) / 2,
  // y = (1 - s^2) / 4, |dx/ds| = sqrt(1/4 + s^2 / 4).
  const int p = m.addCell(mesh::CellType::SEG3, {m.addNode({0, 0, 0}), m.addNode({1, 0, 0}), m.addNode({0.5, 0.25, 0})});
  const auto h = post::modelGaussPoints(m, p, false);
  for (int q = 0; q < 3; ++q) {
    EXPECT_NEAR(h.xyz[3 * q + 1], 0.25 * (1 - xi3[q] * xi3[q]), 1e-15);
    EXPECT_NEAR(h.weights[q], w3[q] * 0.5 * std::sqrt(1 + xi3[q] * xi3[q]), 1e-15);
  }
}
