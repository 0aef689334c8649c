// VERI_JACOBIEN's kernel: the sign of det(dx/dxi) at the Gauss points of the
// elements' rule. Reference answers by hand: the unit square counterclockwise
// has det = 1/4 (QUAD4 on [-1,1]^2) at its 4 points, clockwise -1/4; the
// bow-tie (1,1) <-> (-1,-1) swaps the sign across the cell; a TRIA3 with
// collinear nodes and a SEG2 of zero length have det = 0 everywhere.
#include <gtest/gtest.h>

#include "fem/jacobian_check.hpp"

using aster::fem::jacobianSigns;
using aster::mesh::CellType;
using aster::mesh::Mesh;

namespace {

Mesh cell(CellType t, const std::vector<Eigen::Vector3d>& x) {
  Mesh m;
  std::vector<int> nodes;
  for (const auto& p : x) nodes.push_back(m.addNode(p));
  m.addCell(t, nodes);
  return m;
}

}  // namespace

TEST(JacobianCheck, Quad4CounterclockwiseClockwiseAndBowTie) {
  auto s = jacobianSigns(cell(CellType::QUAD4, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}), 0, false);
  EXPECT_EQ(s.positive, 4);
  EXPECT_EQ(s.negative + s.zero, 0);
  EXPECT_DOUBLE_EQ(s.smallest, 0.25);
  s = jacobianSigns(cell(CellType::QUAD4, {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}}), 0, false);
  EXPECT_EQ(s.negative, 4);
  EXPECT_EQ(s.positive + s.zero, 0);
  EXPECT_DOUBLE_EQ(s.smallest, -0.25);
  s = jacobianSigns(cell(CellType::QUAD4, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}), 0, false);
  EXPECT_GT(s.positive, 0);
  EXPECT_GT(s.negative, 0);
}

TEST(JacobianCheck, CollinearTriangleAndZeroLengthSegmentAreDegenerate) {
  auto s = jacobianSigns(cell(CellType::TRIA3, {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}), 0, false);
  EXPECT_EQ(s.zero, 1);
  EXPECT_EQ(s.positive + s.negative, 0);
  s = jacobianSigns(cell(CellType::SEG2, {{1, 1, 0}, {1, 1, 0}}), 0, false);
  EXPECT_EQ(s.zero, 2);
  s = jacobianSigns(cell(CellType::SEG3, {{0, 0, 0}, {2, 0, 0}, {1, 0, 0}}), 0, false);
  EXPECT_EQ(s.positive, 3);
  EXPECT_DOUBLE_EQ(s.smallest, 1.0);  // |dx/dxi| = half the length
  s = jacobianSigns(cell(CellType::POI1, {{0, 0, 0}}), 0, false);  // not checked
  EXPECT_EQ(s.positive + s.negative + s.zero, 0);
}
