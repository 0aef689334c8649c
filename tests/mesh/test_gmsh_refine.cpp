#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <gmsh.h>

#include "core/error.hpp"
#include "mesh/io/aster_format.hpp"
#include "mesh/io/gmsh_format.hpp"
#include "mesh/refine.hpp"

using namespace aster::mesh;

namespace {
const std::string kDir = std::string(ASTER_SOURCE_DIR) + "/meshes/";

using Points = std::vector<std::array<double, 2>>;

Points sortedRounded(Points p) {
  for (auto& x : p)
    for (double& v : x) v = std::round(v * 1e9) / 1e9 + 0.0;
  std::sort(p.begin(), p.end());
  return p;
}

Points nodePoints(const Mesh& m) {
  Points p;
  for (int i = 0; i < m.nodeCount(); ++i) p.push_back({m.node(i)[0], m.node(i)[1]});
  return sortedRounded(p);
}

Points centroids(const Mesh& m, const std::vector<int>& cells) {
  Points p;
  for (int c : cells) {
    std::array<double, 2> s{0, 0};
    const auto n = m.cellNodes(c);
    for (int k : n) s[0] += m.node(k)[0] / n.size(), s[1] += m.node(k)[1] / n.size();
    p.push_back(s);
  }
  return sortedRounded(p);
}

// Every node of a group lies on its exact geometry.
void expectOnLine(const Mesh& m, const std::string& g, int axis, double value) {
  for (int n : m.nodesOfCells(m.cellGroup(g))) EXPECT_NEAR(m.node(n)[axis], value, 1e-9) << g;
}
}  // namespace

TEST(Gmsh, Ssnp150GeoForSeveralN) {
  for (int n : {1, 2, 16}) {
    const Mesh m = readGmshMesh(kDir + "ssnp150.geo", {{{"N", double(n)}}, true});
    EXPECT_EQ(m.countCells(CellType::QUAD8), n * n) << n;
    EXPECT_EQ(m.countCells(CellType::SEG3), 4 * n + 1) << n;
    EXPECT_EQ(m.cellCount(), n * n + 4 * n + 1);
    // (n+1)^2 corners + 2 n (n+1) mid-edge nodes, plus the 3 of MAITRE.
    EXPECT_EQ(m.nodeCount(), (n + 1) * (n + 1) + 2 * n * (n + 1) + 3) << n;
    EXPECT_EQ(m.spaceDimension(), 2);
    EXPECT_EQ(m.cellGroup("SURFACE").size(), std::size_t(n * n));
    for (const char* g : {"BAS", "HAUT", "GAUCHE", "DROITE"}) EXPECT_EQ(m.cellGroup(g).size(), std::size_t(n));
    expectOnLine(m, "BAS", 1, 0.0);
    expectOnLine(m, "HAUT", 1, 1.0);
    expectOnLine(m, "GAUCHE", 0, 0.0);
    expectOnLine(m, "DROITE", 0, 1.0);
    EXPECT_EQ(m.nodeGroup("BAS").size(), std::size_t(2 * n + 1));
    ASSERT_EQ(m.cellGroup("MAITRE").size(), 1u);
    const auto mn = m.cellNodes(m.cellGroup("MAITRE")[0]);
    EXPECT_NEAR(m.node(mn[0])[0], 1.5, 1e-12);
    EXPECT_NEAR(m.node(mn[0])[1], -0.05, 1e-12);
    EXPECT_NEAR(m.node(mn[1])[0], -0.5, 1e-12);
    EXPECT_NEAR(m.node(mn[2])[0], 0.5, 1e-9);
    EXPECT_NEAR(m.node(mn[2])[1], 0.0, 1e-9);
    // Quadrature-free check of the QUAD8 ordering: corners counterclockwise, mid nodes halfway.
    for (int c : m.cellGroup("SURFACE")) {
      const auto q = m.cellNodes(c);
      double area2 = 0;
      for (int i = 0; i < 4; ++i) {
        const auto p = m.node(q[i]), r = m.node(q[(i + 1) % 4]);
        area2 += p[0] * r[1] - r[0] * p[1];
        EXPECT_NEAR((m.node(q[4 + i]) - 0.5 * (p + r)).norm(), 0.0, 1e-9);
      }
      EXPECT_NEAR(area2 / 2, 1.0 / (n * n), 1e-9);
    }
  }
}

TEST(Gmsh, RefiningSsnp150bFourTimesGivesTheGmshN16Mesh) {
  Mesh m = readAsterMesh(kDir + "ssnp150b.mail");
  for (int i = 0; i < 4; ++i) {
    m = refineUniformly(m, m.cellGroup("SURFACE"));
    const int n = 2 << i;  // 2, 4, 8, 16
    EXPECT_EQ(m.countCells(CellType::QUAD8), n * n);
  }
  EXPECT_EQ(m.countCells(CellType::QUAD8), 256);
  EXPECT_EQ(m.countCells(CellType::SEG3), 65);
  EXPECT_EQ(m.cellGroup("MAITRE").size(), 1u);
  EXPECT_EQ(m.cellName(m.cellGroup("MAITRE")[0]), "M5");
  EXPECT_EQ(m.nodesOfCells(m.cellGroup("SURFACE")).size(), 833u);
  EXPECT_EQ(m.nodeCount(), 833 + 3);
  EXPECT_EQ(m.cellGroupNames(), (std::vector<std::string>{"GAUCHE", "HAUT", "DROITE", "BAS", "MAITRE", "SURFACE"}));
  for (const char* g : {"BAS", "HAUT", "GAUCHE", "DROITE"}) EXPECT_EQ(m.cellGroup(g).size(), 16u);
  expectOnLine(m, "BAS", 1, 0.0);
  expectOnLine(m, "HAUT", 1, 1.0);
  expectOnLine(m, "GAUCHE", 0, 0.0);
  expectOnLine(m, "DROITE", 0, 1.0);
  // Every square node is on the 1/32 lattice of the unit square.
  for (int k : m.nodesOfCells(m.cellGroup("SURFACE")))
    for (int d = 0; d < 2; ++d) {
      const double v = m.node(k)[d] * 32;
      EXPECT_NEAR(v, std::round(v), 1e-9);
      EXPECT_GE(m.node(k)[d], -1e-12);
      EXPECT_LE(m.node(k)[d], 1 + 1e-12);
    }
  const Mesh g = readGmshMesh(kDir + "ssnp150.geo", {{{"N", 16}}, true});
  EXPECT_EQ(nodePoints(m), nodePoints(g));
  for (const char* grp : {"SURFACE", "BAS", "HAUT", "GAUCHE", "DROITE", "MAITRE"})
    EXPECT_EQ(centroids(m, m.cellGroup(grp)), centroids(g, g.cellGroup(grp))) << grp;
}

TEST(Refine, CurvedQuad8EdgeStaysOnItsParabola) {
  // One QUAD8 whose bottom edge is the parabola y = x (1 - x) / 2 sampled at 3 nodes:
  // the serendipity map reproduces it exactly, so the new nodes must lie on it.
  Mesh m;
  const std::vector<Eigen::Vector3d> x{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                       {0.5, 0.125, 0}, {1, 0.5, 0}, {0.5, 1, 0}, {0, 0.5, 0}};
  std::vector<int> nodes;
  for (const auto& p : x) nodes.push_back(m.addNode(p));
  m.addCell(CellType::QUAD8, nodes, "Q");
  m.addCell(CellType::SEG3, {0, 1, 4}, "S");
  m.addCellGroup("BOTTOM", {1});
  m.addNodeGroup("CORNERS", {0, 1, 2, 3});
  const Mesh r = refineUniformly(m);
  EXPECT_EQ(r.countCells(CellType::QUAD8), 4);
  EXPECT_EQ(r.countCells(CellType::SEG3), 2);
  EXPECT_EQ(r.nodeCount(), 21);
  ASSERT_EQ(r.cellGroup("BOTTOM").size(), 2u);
  for (int k : r.nodesOfCells(r.cellGroup("BOTTOM"))) {
    const double px = r.node(k)[0];
    EXPECT_NEAR(r.node(k)[1], px * (1 - px) / 2, 1e-14);
  }
  EXPECT_EQ(r.nodeGroup("CORNERS"), (std::vector<int>{0, 1, 2, 3}));
}

TEST(Refine, TrianglesAndLinearCellsShareEdgeNodes) {
  // Two TRIA3 sharing the diagonal of the unit square, plus a SEG2 on y = 0.
  Mesh m;
  for (auto p : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1, 1, 0), Eigen::Vector3d(0, 1, 0)})
    m.addNode(p);
  m.addCell(CellType::TRIA3, {0, 1, 2});
  m.addCell(CellType::TRIA3, {0, 2, 3});
  m.addCell(CellType::SEG2, {0, 1});
  const Mesh r = refineUniformly(m);
  EXPECT_EQ(r.countCells(CellType::TRIA3), 8);
  EXPECT_EQ(r.countCells(CellType::SEG2), 2);
  EXPECT_EQ(r.nodeCount(), 9);  // 4 + 5 edge midpoints
  double area = 0;
  for (int c = 0; c < r.cellCount(); ++c)
    if (r.cellType(c) == CellType::TRIA3) {
      const auto n = r.cellNodes(c);
      const Eigen::Vector3d a = r.node(n[1]) - r.node(n[0]), b = r.node(n[2]) - r.node(n[0]);
      const double s = 0.5 * (a[0] * b[1] - a[1] * b[0]);
      EXPECT_NEAR(s, 0.5 / 4, 1e-14);  // each half-square split in 4 counterclockwise children
      area += s;
    }
  EXPECT_NEAR(area, 1.0, 1e-14);
  Mesh bad;
  for (int i = 0; i < 7; ++i) bad.addNode(Eigen::Vector3d(i, i * i, 0));
  bad.addCell(CellType::TRIA7, {0, 1, 2, 3, 4, 5, 6});
  EXPECT_THROW(refineUniformly(bad), aster::Error);
}

namespace {
std::vector<std::string> sortedNames(const Mesh& m, const std::vector<int>& items, bool cells) {
  std::vector<std::string> out;
  for (int i : items) out.push_back(cells ? m.cellName(i) : m.nodeName(i));
  std::sort(out.begin(), out.end());
  return out;
}
std::vector<std::string> sorted(std::vector<std::string> v) {
  std::sort(v.begin(), v.end());
  return v;
}
// A cell by what it is, "QUAD4 N1 N2 N3 N4": MSH 2.2 renumbers the cells, not the nodes.
std::vector<std::string> cellKeys(const Mesh& m, const std::vector<int>& cells) {
  std::vector<std::string> out;
  for (int c : cells) {
    std::string key = cellTypeName(m.cellType(c));
    for (int n : m.cellNodes(c)) key += " " + m.nodeName(n);
    out.push_back(key);
  }
  std::sort(out.begin(), out.end());
  return out;
}
std::vector<int> allCells(const Mesh& m) {
  std::vector<int> out(m.cellCount());
  for (int c = 0; c < m.cellCount(); ++c) out[c] = c;
  return out;
}
}  // namespace

TEST(Gmsh, WriteReadRoundTripAllFormats) {
  Mesh m = readAsterMesh(kDir + "ssnp150b.mail");
  m = refineUniformly(m, m.cellGroup("SURFACE"));
  // Overlapping groups: BAS (2 SEG3) is also in BAS_ET_SURF with the 4 QUAD8.
  std::vector<int> both = m.cellGroup("BAS");
  for (int c : m.cellGroup("SURFACE")) both.push_back(c);
  m.addCellGroup("BAS_ET_SURF", both);
  for (double version : {2.2, 4.1})
    for (bool binary : {false, true}) {
      const std::string path = std::string(ASTER_BINARY_DIR) + "/mesh_roundtrip.msh";
      writeGmshMesh(m, path, {version, binary});
      const Mesh r = readGmshMesh(path);
      ASSERT_EQ(r.nodeCount(), m.nodeCount()) << version << binary;
      ASSERT_EQ(r.cellCount(), m.cellCount());
      for (int i = 0; i < m.nodeCount(); ++i)
        EXPECT_EQ((r.node(r.nodeIndex("N" + std::to_string(i + 1))) - m.node(i)).norm(), 0.0);
      EXPECT_EQ(cellKeys(r, allCells(r)), cellKeys(m, allCells(m)));
      // 4.1 keeps the cell tags, and so does aster-lite's own 2.2 ASCII writer (msh2_writer.hpp).
      if (version == 4.1 || !binary)
        for (int c = 0; c < m.cellCount(); ++c) {
          const int rc = r.cellIndex("M" + std::to_string(c + 1));
          EXPECT_EQ(cellKeys(r, {rc}), cellKeys(m, {c}));
        }
      const auto expected = sorted(m.cellGroupNames());
      ASSERT_EQ(expected.size(), 7u);
      ASSERT_EQ(sorted(r.cellGroupNames()), expected);
      // The reader makes one GROUP_NO per GROUP_MA: the nodes of its cells.
      ASSERT_EQ(sorted(r.nodeGroupNames()), expected);
      for (const auto& g : expected) {
        EXPECT_EQ(cellKeys(r, r.cellGroup(g)), cellKeys(m, m.cellGroup(g))) << g;
        EXPECT_EQ(sortedNames(r, r.nodeGroup(g), false), sortedNames(m, m.nodesOfCells(m.cellGroup(g)), false)) << g;
      }
      // Hand-counted: BAS is 2 SEG3 on y = 0 (5 nodes), SURFACE 4 QUAD8 (21 nodes), MAITRE 1 SEG3.
      EXPECT_EQ(r.nodeGroup("BAS").size(), 5u);
      for (int n : r.nodeGroup("BAS")) EXPECT_EQ(r.node(n)[1], 0.0);
      EXPECT_EQ(r.nodeGroup("SURFACE").size(), 21u);
      EXPECT_EQ(r.nodeGroup("MAITRE").size(), 3u);
      EXPECT_EQ(r.cellGroup("BAS_ET_SURF").size(), 6u);
      EXPECT_EQ(r.nodeGroup("BAS_ET_SURF").size(), 21u);
    }
}

TEST(Gmsh, UngroupedCellsAndPoi1SurviveARoundTrip) {
  // The unit square: one QUAD4 in S, an ungrouped SEG2 on y = 0, a POI1 on
  // (0, 0) in no group and a POI1 on (1, 1) in P.
  Mesh m;
  for (auto p : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1, 1, 0), Eigen::Vector3d(0, 1, 0)})
    m.addNode(p);
  m.addCell(CellType::QUAD4, {0, 1, 2, 3});
  m.addCell(CellType::SEG2, {0, 1});
  m.addCell(CellType::POI1, {0});
  m.addCell(CellType::POI1, {2});
  m.addCellGroup("S", {0});
  m.addCellGroup("P", {3});
  for (double version : {2.2, 4.1})
    for (bool binary : {false, true}) {
      const std::string path = std::string(ASTER_BINARY_DIR) + "/mesh_poi1.msh";
      writeGmshMesh(m, path, {version, binary});
      const Mesh r = readGmshMesh(path);
      ASSERT_EQ(r.cellCount(), 4) << version << binary;
      EXPECT_EQ(cellKeys(r, allCells(r)),
                (std::vector<std::string>{"POI1 N1", "POI1 N3", "QUAD4 N1 N2 N3 N4", "SEG2 N1 N2"}));
      EXPECT_EQ(r.nodeCount(), 4);
      // The reserved group is no GROUP_MA, and the groups stay exact (no SaveAll).
      EXPECT_EQ(sorted(r.cellGroupNames()), (std::vector<std::string>{"P", "S"}));
      EXPECT_EQ(sorted(r.nodeGroupNames()), (std::vector<std::string>{"P", "S"}));
      EXPECT_EQ(cellKeys(r, r.cellGroup("P")), std::vector<std::string>{"POI1 N3"});
      EXPECT_EQ(sortedNames(r, r.nodeGroup("P"), false), std::vector<std::string>{"N3"});
      EXPECT_EQ(cellKeys(r, r.cellGroup("S")), std::vector<std::string>{"QUAD4 N1 N2 N3 N4"});
      EXPECT_EQ(sortedNames(r, r.nodeGroup("S"), false), (std::vector<std::string>{"N1", "N2", "N3", "N4"}));
      if (version == 4.1 || !binary) {
        EXPECT_EQ(cellKeys(r, {r.cellIndex("M3")}), std::vector<std::string>{"POI1 N1"});
        EXPECT_EQ(cellKeys(r, {r.cellIndex("M4")}), std::vector<std::string>{"POI1 N3"});
      }
      if (!binary) {
        std::ifstream in(path);
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        EXPECT_NE(text.find(std::string("\"") + kGmshUngroupedName + "\""), std::string::npos);
      }
    }
}

TEST(Gmsh, PointsOfGmshOwnVerticesAreStillDropped) {
  // As gmsh writes them: a point element on geometric vertex 1 (physical 0, i.e.
  // none) and the QUAD4 of surface 1; then the same with the point in physical 5.
  const std::string path = std::string(ASTER_BINARY_DIR) + "/mesh_gmsh_points.msh";
  const std::string head =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndNodes\n"
      "$Elements\n2\n";
  std::ofstream(path) << head << "1 15 2 0 1 1\n2 3 2 0 1 1 2 3 4\n$EndElements\n";
  const Mesh r = readGmshMesh(path);
  ASSERT_EQ(r.cellCount(), 1);
  EXPECT_EQ(r.cellType(0), CellType::QUAD4);
  EXPECT_TRUE(r.cellGroupNames().empty());
  std::ofstream(path) << head << "1 15 2 5 1 1\n2 3 2 0 1 1 2 3 4\n$EndElements\n";
  const Mesh g = readGmshMesh(path);
  ASSERT_EQ(g.cellCount(), 2);
  EXPECT_EQ(g.countCells(CellType::POI1), 1);
  EXPECT_EQ(g.cellGroupNames(), std::vector<std::string>{"GM5"});
  EXPECT_EQ(sortedNames(g, g.nodeGroup("GM5"), false), std::vector<std::string>{"N1"});
}

TEST(Gmsh, ResultsFileHoldsTheNodalFieldsPerInstant) {
  const Mesh m = readAsterMesh(kDir + "ssnp150b.mail");
  std::vector<FieldInstant> instants;
  for (int s = 0; s < 2; ++s) {
    FieldInstant inst{s, 0.5 * (s + 1), {}};
    NodalField f{"DEPL", {"DX", "DY"}, {}};
    for (int i = 0; i < m.nodeCount(); ++i) f.values.insert(f.values.end(), {m.node(i)[0] * (s + 1), -m.node(i)[1]});
    inst.fields.push_back(f);
    instants.push_back(inst);
  }
  for (double version : {2.2, 4.1}) {
  const std::string path = std::string(ASTER_BINARY_DIR) + "/mesh_results.msh";
  writeGmshResults(m, path, instants, {version, false});
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::open(path);
  std::vector<int> views;
  gmsh::view::getTags(views);
  ASSERT_EQ(views.size(), 1u);
  std::string type;
  std::vector<std::size_t> tags;
  std::vector<std::vector<double>> data;
  double time = 0;
  int nc = 0;
  gmsh::view::getModelData(views[0], 1, type, tags, data, time, nc);
  EXPECT_EQ(type, "NodeData");
  EXPECT_EQ(nc, 3);
  EXPECT_DOUBLE_EQ(time, 1.0);
  ASSERT_EQ(tags.size(), 11u);
  for (std::size_t k = 0; k < tags.size(); ++k) {
    const int i = static_cast<int>(tags[k]) - 1;
    EXPECT_DOUBLE_EQ(data[k][0], 2 * m.node(i)[0]);
    EXPECT_DOUBLE_EQ(data[k][1], -m.node(i)[1]);
    EXPECT_DOUBLE_EQ(data[k][2], 0.0);
  }
  gmsh::finalize();
  }
}

TEST(Gmsh, MalformedFileIsAnError) {
  const std::string path = std::string(ASTER_BINARY_DIR) + "/mesh_bad.msh";
  std::ofstream(path) << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n";
  EXPECT_THROW(readGmshMesh(path), aster::Error);
  EXPECT_THROW(readGmshMesh(kDir + "does-not-exist.msh"), aster::Error);
}
