// mesh::inwardSegments, the check behind AFFE_CHAR_MECA's VERI_NORM: it finds the
// boundary segments whose normal (dy, -dx) points into their 2D cell, and changes
// nothing. ssnp150b.mail walks its four sides clockwise around a counterclockwise
// QUAD8 (inward normals); MAITRE touches no 2D cell (no outward side, not judged).
#include <gtest/gtest.h>

#include "mesh/group_ops.hpp"
#include "mesh/io/aster_format.hpp"
#include "mesh/orient.hpp"

using namespace aster::mesh;

TEST(InwardSegments, FindsTheReversedSidesWithTheirCellAndChangesNothing) {
  Mesh m = readAsterMesh(std::string(ASTER_SOURCE_DIR) + "/meshes/ssnp150b.mail");
  const std::vector<int> sides = unionOfCellGroups(m, {"GAUCHE", "HAUT", "DROITE", "BAS"});
  const int quad = m.cellGroup("SURFACE")[0];
  const auto before = m.cellNodes(sides[0]);
  auto inward = inwardSegments(m, sides);
  ASSERT_EQ(inward.size(), 4u);
  for (std::size_t i = 0; i < inward.size(); ++i) {
    EXPECT_EQ(inward[i].segment, sides[i]);
    EXPECT_EQ(inward[i].cell, quad);
  }
  EXPECT_EQ(m.cellNodes(sides[0])[0], before[0]);  // untouched
  // The master touches no 2D cell, the QUAD8 is no segment: neither is judged.
  EXPECT_TRUE(inwardSegments(m, m.cellGroup("MAITRE")).empty());
  EXPECT_TRUE(inwardSegments(m, m.cellGroup("SURFACE")).empty());
  // Once oriented (MODI_MAILLAGE ORIE_PEAU), nothing is left.
  orientBoundarySegments(m, sides);
  EXPECT_TRUE(inwardSegments(m, sides).empty());
  // One side turned back is found alone.
  reverseSegment(m, m.cellGroup("HAUT")[0]);
  inward = inwardSegments(m, sides);
  ASSERT_EQ(inward.size(), 1u);
  EXPECT_EQ(inward[0].segment, m.cellGroup("HAUT")[0]);
}

TEST(InwardSegments, ASegmentBetweenTwoCellsIsNotJudged) {
  // Two QUAD4 side by side; the SEG2 on their common edge has no outward side.
  Mesh m;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) m.addNode(Eigen::Vector3d(i, j, 0));
  m.addCell(CellType::QUAD4, {0, 1, 4, 3});
  m.addCell(CellType::QUAD4, {1, 2, 5, 4});
  const int inner = m.addCell(CellType::SEG2, {1, 4});
  const int bottomOut = m.addCell(CellType::SEG2, {0, 1});  // outward (normal (0, -1))
  const int bottomIn = m.addCell(CellType::SEG2, {2, 1});   // inward (normal (0, 1))
  const auto inward = inwardSegments(m, {inner, bottomOut, bottomIn});
  ASSERT_EQ(inward.size(), 1u);
  EXPECT_EQ(inward[0].segment, bottomIn);
  EXPECT_EQ(inward[0].cell, 1);
}
