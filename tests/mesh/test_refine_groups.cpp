// Groups of nodes through uniform refinement. The rectangle [0,2] x [0,1] of two
// QUAD4 (N1 N2 N3 along y = 0, N4 N5 N6 along y = 1) refined once: the new
// nodes are the 7 edge middles and the 2 centres, created in that order by
// cell, so a new node is identified here by its coordinates.
#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "mesh/refine.hpp"

using namespace aster::mesh;

namespace {

Mesh rectangle() {
  Mesh m;
  for (auto p : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(2, 0, 0),
                 Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(1, 1, 0), Eigen::Vector3d(2, 1, 0)})
    m.addNode(p);
  m.addCell(CellType::QUAD4, {0, 1, 4, 3}, "Q1");
  m.addCell(CellType::QUAD4, {1, 2, 5, 4}, "Q2");
  m.addCell(CellType::SEG2, {3, 0}, "S_LEFT");
  m.addCell(CellType::SEG2, {0, 1}, "S_BOTTOM1");
  m.addCell(CellType::SEG2, {1, 2}, "S_BOTTOM2");
  m.addCellGroup("SURFACE", {0, 1});
  m.addCellGroup("GAUCHE", {2});
  m.addCellGroup("BAS", {3, 4});
  return m;
}

int nodeAt(const Mesh& m, double x, double y) {
  for (int n = 0; n < m.nodeCount(); ++n)
    if ((m.node(n) - Eigen::Vector3d(x, y, 0)).norm() < 1e-12) return n;
  return -1;
}

std::string errorOf(const Mesh& m) {
  try {
    refineUniformly(m);
  } catch (const aster::Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(RefineNodeGroups, AGroupWithTheNodesOfACellGroupFollowsIt) {
  Mesh m = rectangle();
  m.addNodeGroup("GAUCHE", {3, 0});          // the nodes of GROUP_MA GAUCHE
  m.addNodeGroup("TOUT", {5, 4, 3, 2, 1, 0});  // those of SURFACE, in another order
  m.addNodeGroup("P1", {0});                 // a point: no new node between
  m.addNodeGroup("DIAGONAL", {0, 5});        // no edge joins them
  const Mesh r = refineUniformly(m);
  ASSERT_EQ(r.nodeCount(), 15);
  EXPECT_EQ(r.nodeGroup("GAUCHE"), (std::vector<int>{3, nodeAt(r, 0, 0.5), 0}));  // its one segment, in order
  std::vector<int> all = r.nodeGroup("TOUT");
  EXPECT_EQ(std::vector<int>(all.begin(), all.begin() + 6), (std::vector<int>{5, 4, 3, 2, 1, 0}));  // old, in order
  std::sort(all.begin(), all.end());
  std::vector<int> every(15);
  for (int n = 0; n < 15; ++n) every[n] = n;
  EXPECT_EQ(all, every);
  EXPECT_EQ(r.nodeGroup("P1"), (std::vector<int>{0}));
  EXPECT_EQ(r.nodeGroup("DIAGONAL"), (std::vector<int>{0, 5}));
}

TEST(RefineNodeGroups, AnOrderedChainStaysOrdered) {
  Mesh m = rectangle();
  m.addNodeGroup("BAS_ORD", {2, 1, 0});  // NOEUD_ORDO of BAS from N3
  m.addNodeGroup("BAS_SET", {1, 0, 2});  // the same nodes, not in chain order
  const Mesh r = refineUniformly(m);
  const int m1 = nodeAt(r, 0.5, 0), m2 = nodeAt(r, 1.5, 0);
  EXPECT_EQ(r.nodeGroup("BAS_ORD"), (std::vector<int>{2, m2, 1, m1, 0}));
  EXPECT_EQ(r.nodeGroup("BAS_SET"), (std::vector<int>{1, 0, 2, std::min(m1, m2), std::max(m1, m2)}));
}

TEST(RefineNodeGroups, AGroupANewNodeLiesInWithoutCellsIsRefused) {
  Mesh m = rectangle();
  m.addNodeGroup("P1", {0});
  m.addNodeGroup("ENCASTRE", {0, 3});  // the left edge, but no GROUP_MA of its nodes only
  m.removeCellGroup("GAUCHE");
  const std::string e = errorOf(m);
  const Mesh r = [] {  // the node the message names: the middle of N1 N4
    Mesh ok = rectangle();
    return refineUniformly(ok);
  }();
  EXPECT_EQ(e.rfind("GROUP_NO 'ENCASTRE': the new node " + r.nodeName(nodeAt(r, 0, 0.5)) +
                        " lies between its nodes N4, N1 and no group of cells has exactly its nodes. "
                        "Which new nodes belong to such a group of nodes cannot be told",
                    0),
            0u)
      << e;
  EXPECT_NE(e.find("DEFI_GROUP DETR_GROUP_NO"), std::string::npos) << e;
  EXPECT_EQ(e.find("P1"), std::string::npos) << e;
}

TEST(RefineNodeGroups, TwoCellGroupsWithTheSameNodesThatRefineDifferentlyAreRefused) {
  // A triangle and two of its edges: the same 3 nodes, but the triangle's
  // refined cells also hold the middle of the third edge.
  Mesh m;
  for (auto p : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)}) m.addNode(p);
  m.addCell(CellType::TRIA3, {0, 1, 2});
  m.addCell(CellType::SEG2, {0, 1});
  m.addCell(CellType::SEG2, {1, 2});
  m.addCellGroup("TRIANGLE", {0});
  m.addCellGroup("EDGES", {1, 2});
  m.addNodeGroup("X", {0, 1, 2});
  EXPECT_EQ(errorOf(m).rfind("GROUP_NO 'X' has exactly the nodes of the groups of cells 'TRIANGLE' and 'EDGES', "
                             "whose refined cells have different nodes. ",
                             0),
            0u)
      << errorOf(m);
  m.removeCellGroup("EDGES");
  EXPECT_EQ(refineUniformly(m).nodeGroup("X").size(), 6u);
}
