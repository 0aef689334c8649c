// CREA_MAILLAGE's mesh operations (mesh/cell_conversion.hpp, mesh/lac_patches.hpp)
// on small meshes whose expected result is counted or placed by hand: node
// counts by Euler's formula (a disk of V vertices and F cells has V + F - 1
// edges), middle nodes at the edge midpoints, centre nodes at the image of
// the reference centre of a known isoparametric map.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <string>

#include "core/error.hpp"
#include "mesh/cell_conversion.hpp"
#include "mesh/lac_patches.hpp"

using namespace aster::mesh;

namespace {

// An nx x ny grid of [0, nx] x [0, ny], slightly distorted, in QUAD4 (or
// each quadrangle cut into two TRIA3), with its boundary in SEG2 cells.
// Groups: SURFACE, BAS (bottom segments), BORD (every segment), CELL1 (the
// first cell); node groups P1 (origin) and COIN (the four corners).
Mesh grid(int nx, int ny, bool triangles) {
  Mesh m;
  auto id = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const bool inner = i > 0 && i < nx && j > 0 && j < ny;
      m.addNode(Eigen::Vector3d(i + (inner ? 0.1 * std::sin(i + 2.0 * j) : 0.0), j + (inner ? 0.07 * i : 0.0), 0));
    }
  std::vector<int> surface, bottom, border;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (triangles) {
        surface.push_back(m.addCell(CellType::TRIA3, {a, b, c}));
        surface.push_back(m.addCell(CellType::TRIA3, {a, c, d}));
      } else {
        surface.push_back(m.addCell(CellType::QUAD4, {a, b, c, d}));
      }
    }
  for (int i = 0; i < nx; ++i) bottom.push_back(m.addCell(CellType::SEG2, {id(i, 0), id(i + 1, 0)}));
  border = bottom;
  for (int j = 0; j < ny; ++j) border.push_back(m.addCell(CellType::SEG2, {id(nx, j), id(nx, j + 1)}));
  for (int i = nx; i > 0; --i) border.push_back(m.addCell(CellType::SEG2, {id(i, ny), id(i - 1, ny)}));
  for (int j = ny; j > 0; --j) border.push_back(m.addCell(CellType::SEG2, {id(0, j), id(0, j - 1)}));
  m.addCellGroup("SURFACE", surface);
  m.addCellGroup("BAS", bottom);
  m.addCellGroup("BORD", border);
  m.addCellGroup("CELL1", {0});
  m.addNodeGroup("P1", {0});
  m.addNodeGroup("COIN", {id(0, 0), id(nx, 0), id(nx, ny), id(0, ny)});
  return m;
}

std::vector<int> allCells(const Mesh& m) {
  std::vector<int> all(m.cellCount());
  for (int c = 0; c < m.cellCount(); ++c) all[c] = c;
  return all;
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const aster::Error& e) {
    return e.what();
  }
  return "";
}

void expectSameMesh(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.nodeCount(), b.nodeCount());
  for (int n = 0; n < a.nodeCount(); ++n) {
    EXPECT_EQ(a.nodeName(n), b.nodeName(n));
    EXPECT_EQ((a.node(n) - b.node(n)).norm(), 0.0);
  }
  ASSERT_EQ(a.cellCount(), b.cellCount());
  for (int c = 0; c < a.cellCount(); ++c) {
    EXPECT_EQ(a.cellType(c), b.cellType(c));
    EXPECT_EQ(a.cellName(c), b.cellName(c));
    EXPECT_EQ(std::vector<int>(a.cellNodes(c).begin(), a.cellNodes(c).end()),
              std::vector<int>(b.cellNodes(c).begin(), b.cellNodes(c).end()));
  }
  EXPECT_EQ(a.cellGroupNames(), b.cellGroupNames());
  for (const auto& g : a.cellGroupNames()) EXPECT_EQ(a.cellGroup(g), b.cellGroup(g));
  EXPECT_EQ(a.nodeGroupNames(), b.nodeGroupNames());
  for (const auto& g : a.nodeGroupNames()) EXPECT_EQ(a.nodeGroup(g), b.nodeGroup(g));
}

// LINE_QUAD of the grid: counts, midpoints, shared middle nodes, segments.
void checkLineQuad(bool triangles) {
  const int nx = 4, ny = 3;
  const Mesh in = grid(nx, ny, triangles);
  const Mesh out = lineToQuadratic(in, allCells(in), "NS", 1);
  const int V = (nx + 1) * (ny + 1), F = triangles ? 2 * nx * ny : nx * ny;
  const int edges = V + F - 1;
  ASSERT_EQ(out.nodeCount(), V + edges);
  for (int k = 0; k < edges; ++k) EXPECT_EQ(out.nodeName(V + k), "NS" + std::to_string(k + 1));
  ASSERT_EQ(out.cellCount(), in.cellCount());
  std::map<int, int> cellsOnMiddle;  // middle node -> 2D cells using it
  for (int c = 0; c < out.cellCount(); ++c) {
    const CellType t = in.cellType(c);
    const CellType expected = t == CellType::SEG2 ? CellType::SEG3 : t == CellType::TRIA3 ? CellType::TRIA6 : CellType::QUAD8;
    ASSERT_EQ(out.cellType(c), expected);
    EXPECT_EQ(out.cellName(c), in.cellName(c));
    const auto n = out.cellNodes(c);
    const int corners = vertexCount(t);
    for (int i = 0; i < corners; ++i) EXPECT_EQ(n[i], in.cellNodes(c)[i]);  // the vertices are kept
    const int edgesOfCell = corners == 2 ? 1 : corners;
    for (int e = 0; e < edgesOfCell; ++e) {
      const int mid = n[corners + e];
      EXPECT_GE(mid, V);
      const Eigen::Vector3d expectedX = 0.5 * (out.node(n[e]) + out.node(n[(e + 1) % corners]));
      EXPECT_LT((out.node(mid) - expectedX).norm(), 1e-15);
      if (t != CellType::SEG2) ++cellsOnMiddle[mid];
    }
  }
  // Each edge has one node: an inner edge's is used by 2 cells, a boundary edge's by 1.
  const int boundaryEdges = 2 * (nx + ny);
  int inner = 0, boundary = 0;
  for (const auto& [node, count] : cellsOnMiddle) (count == 2 ? inner : boundary) += 1;
  EXPECT_EQ(boundary, boundaryEdges);
  EXPECT_EQ(inner, edges - boundaryEdges);
  // Groups: same cells; nodes unchanged (the new nodes join none).
  for (const auto& g : in.cellGroupNames()) EXPECT_EQ(out.cellGroup(g), in.cellGroup(g));
  EXPECT_EQ(out.nodeGroup("COIN"), in.nodeGroup("COIN"));
  EXPECT_EQ(out.nodesOfCells(out.cellGroup("BAS")).size(), 2u * nx + 1);
  // And back.
  expectSameMesh(quadraticToLinear(out, allCells(out)), in);
}

}  // namespace

TEST(LineQuad, Quadrangles) { checkLineQuad(false); }
TEST(LineQuad, Triangles) { checkLineQuad(true); }

TEST(LineQuad, OnlyTheCellsGivenAndPrefix) {
  const Mesh in = grid(2, 1, false);
  // The bottom segments only: 2 edges, 2 new nodes; the quadrangles stay QUAD4.
  const Mesh out = lineToQuadratic(in, in.cellGroup("BAS"), "X", 7);
  ASSERT_EQ(out.nodeCount(), in.nodeCount() + 2);
  EXPECT_EQ(out.nodeName(in.nodeCount()), "X7");
  EXPECT_EQ(out.nodeName(in.nodeCount() + 1), "X8");
  EXPECT_EQ(out.countCells(CellType::QUAD4), 2);
  EXPECT_EQ(out.countCells(CellType::SEG3), 2);
  // A name that exists is refused.
  Mesh named = in;
  named.addNode(Eigen::Vector3d(9, 9, 0), "NS1");
  EXPECT_NE(errorOf([&] { lineToQuadratic(named, allCells(named), "NS", 1); }).find("NS1 is already a node's"),
            std::string::npos);
}

TEST(QuadLine, DroppedNodesLeaveTheNodeGroups) {
  Mesh in = grid(2, 1, false);
  Mesh q = lineToQuadratic(in, allCells(in), "NS", 1);
  const int mid = q.cellNodes(0)[4];  // the middle of the first quadrangle's bottom edge
  q.addNodeGroup("AVEC_MILIEU", {0, mid, 1});
  const Mesh back = quadraticToLinear(q, allCells(q));
  EXPECT_EQ(back.nodeCount(), in.nodeCount());
  EXPECT_EQ(back.nodeGroup("AVEC_MILIEU"), (std::vector<int>{0, 1}));
  // Converting the quadrangles only keeps the nodes the segments still use.
  const Mesh partial = quadraticToLinear(q, q.cellGroup("SURFACE"));
  EXPECT_EQ(partial.nodeCount(), in.nodeCount() + static_cast<int>(in.cellGroup("BORD").size()));
  EXPECT_EQ(partial.nodeGroup("AVEC_MILIEU").size(), 3u);
}

TEST(ModiMaille, Quad8To9CentreIsTheImageOfTheReferenceCentre) {
  // x = 0.3 + xi + 0.1 eta^2 + 0.05 xi eta, y = -0.2 + eta + 0.2 xi^2 + 0.03 xi^2 eta: in the
  // QUAD8 space, so the QUAD8 of these nodes has this map, and its centre is (0.3, -0.2).
  auto X = [](double xi, double eta) {
    return Eigen::Vector3d(0.3 + xi + 0.1 * eta * eta + 0.05 * xi * eta, -0.2 + eta + 0.2 * xi * xi + 0.03 * xi * xi * eta, 0);
  };
  const double ref[8][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {0, -1}, {1, 0}, {0, 1}, {-1, 0}};
  Mesh m;
  std::vector<int> nodes;
  for (const auto& r : ref) nodes.push_back(m.addNode(X(r[0], r[1])));
  m.addCell(CellType::QUAD8, nodes, "Q");
  m.addCellGroup("G", {0});
  const Mesh out = addCentreNodes(m, {0}, "QUAD8_9", "NS", 1);
  ASSERT_EQ(out.cellType(0), CellType::QUAD9);
  ASSERT_EQ(out.nodeCount(), 9);
  EXPECT_EQ(out.cellNodes(0)[8], 8);
  EXPECT_EQ(out.nodeName(8), "NS1");
  EXPECT_LT((out.node(8) - Eigen::Vector3d(0.3, -0.2, 0)).norm(), 1e-15);
  EXPECT_EQ(out.cellGroup("G"), std::vector<int>{0});
}

TEST(ModiMaille, Tria6To7CentreIsTheImageOfTheReferenceCentre) {
  // x = 0.1 + r + 0.2 s^2, y = s + 0.3 r s (quadratic): the centre (1/3, 1/3) maps to
  // (0.1 + 1/3 + 0.2/9, 1/3 + 0.3/9).
  auto X = [](double r, double s) { return Eigen::Vector3d(0.1 + r + 0.2 * s * s, s + 0.3 * r * s, 0); };
  const double ref[6][2] = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
  Mesh m;
  std::vector<int> nodes;
  for (const auto& r : ref) nodes.push_back(m.addNode(X(r[0], r[1])));
  m.addCell(CellType::TRIA6, nodes, "T");
  const Mesh out = addCentreNodes(m, {0}, "TRIA6_7", "C", 5);
  ASSERT_EQ(out.cellType(0), CellType::TRIA7);
  EXPECT_EQ(out.nodeName(6), "C5");
  EXPECT_LT((out.node(6) - Eigen::Vector3d(0.1 + 1.0 / 3 + 0.2 / 9, 1.0 / 3 + 0.3 / 9, 0)).norm(), 1e-15);
  EXPECT_NE(errorOf([&] { addCentreNodes(m, {0}, "SEG3_4", "NS", 1); }).find("SEG3_4"), std::string::npos);
}

TEST(DecoupeLac, QuadrangleCutInFourUnderItsSlaveSegment) {
  // [0, 3] x [0, 1], the slave segment on the top edge, run from right to left.
  Mesh m;
  for (auto p : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(3, 0, 0), Eigen::Vector3d(3, 1, 0), Eigen::Vector3d(0, 1, 0)})
    m.addNode(p);
  m.addCell(CellType::QUAD4, {0, 1, 2, 3}, "Q");
  m.addCell(CellType::SEG2, {2, 3}, "S");
  m.addCellGroup("VOLUME", {0});
  m.addCellGroup("ESCL", {1});
  m.addNodeGroup("HAUT", {2, 3});
  const LacPatches lac = cutLacPatches(m, {1});
  const Mesh& out = lac.mesh;
  ASSERT_EQ(out.nodeCount(), 8);
  // On the top edge, 1/3 and 2/3 of the way (from local node 2 at x = 3); inside, half way up.
  std::set<std::pair<double, double>> added;
  for (int n = 4; n < 8; ++n) added.insert({out.node(n).x(), out.node(n).y()});
  EXPECT_EQ(added, (std::set<std::pair<double, double>>{{2, 1}, {1, 1}, {2, 0.5}, {1, 0.5}}));
  EXPECT_EQ(out.nodeName(4).substr(0, 1), "C");
  EXPECT_EQ(out.nodeName(6).substr(0, 1), "L");
  ASSERT_EQ(out.cellGroup("VOLUME").size(), 4u);
  double area = 0;
  for (int c : out.cellGroup("VOLUME")) {
    ASSERT_EQ(out.cellType(c), CellType::QUAD4);
    const auto n = out.cellNodes(c);
    double a = 0;  // shoelace: positive for counterclockwise
    for (int i = 0; i < 4; ++i) a += out.node(n[i]).x() * out.node(n[(i + 1) % 4]).y() - out.node(n[(i + 1) % 4]).x() * out.node(n[i]).y();
    EXPECT_GT(a, 0);
    area += 0.5 * a;
  }
  EXPECT_NEAR(area, 3.0, 1e-14);
  // The slave segment in three, in its own direction, chained.
  const auto& slave = out.cellGroup("ESCL");
  ASSERT_EQ(slave.size(), 3u);
  EXPECT_EQ(lac.patches, (std::vector<std::vector<int>>{slave}));
  EXPECT_EQ(out.cellNodes(slave[0])[0], 2);
  EXPECT_EQ(out.cellNodes(slave[2])[1], 3);
  for (int k = 0; k < 3; ++k) {
    const auto n = out.cellNodes(slave[k]);
    EXPECT_NEAR((out.node(n[1]) - out.node(n[0])).norm(), 1.0, 1e-14);
    EXPECT_LT(out.node(n[1]).x(), out.node(n[0]).x());
    if (k > 0) {
      EXPECT_EQ(n[0], out.cellNodes(slave[k - 1])[1]);
    }
  }
  EXPECT_EQ(out.nodeGroup("HAUT"), (std::vector<int>{2, 3}));  // groups of nodes unchanged
}

TEST(DecoupeLac, TriangleCutInTwoQuadraticUnchanged) {
  Mesh tri = grid(1, 1, true);  // 2 triangles, the bottom segment under the first
  const LacPatches lac = cutLacPatches(tri, tri.cellGroup("BAS"));
  ASSERT_EQ(lac.mesh.nodeCount(), 5);
  EXPECT_LT((lac.mesh.node(4) - Eigen::Vector3d(0.5, 0, 0)).norm(), 1e-15);
  EXPECT_EQ(lac.mesh.cellGroup("BAS").size(), 2u);
  EXPECT_EQ(lac.mesh.cellGroup("SURFACE").size(), 3u);
  EXPECT_EQ(lac.mesh.cellGroup("CELL1").size(), 2u);  // the children of the first triangle
  // Quadratic cells are their own patch: the mesh is the same.
  const Mesh quad = lineToQuadratic(grid(2, 2, false), allCells(grid(2, 2, false)), "NS", 1);
  const LacPatches same = cutLacPatches(quad, quad.cellGroup("BAS"));
  expectSameMesh(same.mesh, quad);
  EXPECT_EQ(same.patches.size(), 2u);
}

TEST(DecoupeLac, RefusedCases) {
  const Mesh m = grid(1, 1, false);
  // Two slave segments (bottom and right) on the one quadrangle.
  const std::string two = errorOf([&] { cutLacPatches(m, m.cellGroup("BORD")); });
  EXPECT_NE(two.find("also bears the slave cell"), std::string::npos) << two;
  const std::string surface = errorOf([&] { cutLacPatches(m, {0}); });
  EXPECT_NE(surface.find("(QUAD4): DECOUPE_LAC cuts patches under segments"), std::string::npos) << surface;
  Mesh inner = grid(2, 1, false);
  inner.addCell(CellType::SEG2, {1, 4}, "INNER");  // the edge between the two quadrangles
  const std::string between = errorOf([&] { cutLacPatches(inner, {inner.cellIndex("INNER")}); });
  EXPECT_NE(between.find("lies between two 2D cells"), std::string::npos) << between;
}
