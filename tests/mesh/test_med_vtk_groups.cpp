#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "mesh/group_ops.hpp"
#include "mesh/io/aster_format.hpp"
#include "mesh/io/med_format.hpp"
#include "mesh/io/vtk_format.hpp"
#include "mesh/node_ordering.hpp"
#include "mesh/orient.hpp"
#include "mesh/refine.hpp"

using namespace aster::mesh;

namespace {
const std::string kDir = std::string(ASTER_SOURCE_DIR) + "/meshes/";
const std::string kOut = std::string(ASTER_BINARY_DIR) + "/";

Mesh refinedSsnp150b() {
  Mesh m = readAsterMesh(kDir + "ssnp150b.mail");
  m = refineUniformly(m, m.cellGroup("SURFACE"));
  m.addNodeGroup("COINS", {0, 1, 2, 3});
  m.addCellGroup("BAS_ET_SURF", unionOfCellGroups(m, {"BAS", "SURFACE"}));  // overlapping groups
  return m;
}

std::vector<std::string> cellNames(const Mesh& m, const std::vector<int>& cells) {
  std::vector<std::string> out;
  for (int c : cells) out.push_back(m.cellName(c));
  std::sort(out.begin(), out.end());
  return out;
}
}  // namespace

TEST(Med, WriteReadRoundTripKeepsEverything) {
  const Mesh m = refinedSsnp150b();
  writeMedMesh(m, kOut + "mesh_roundtrip.med");
  const Mesh r = readMedMesh(kOut + "mesh_roundtrip.med");
  EXPECT_EQ(r.spaceDimension(), 3);
  ASSERT_EQ(r.nodeCount(), m.nodeCount());
  ASSERT_EQ(r.cellCount(), m.cellCount());
  for (int i = 0; i < m.nodeCount(); ++i) {
    EXPECT_EQ(r.nodeName(i), m.nodeName(i));
    EXPECT_EQ(r.node(i), m.node(i));
  }
  for (int c = 0; c < m.cellCount(); ++c) {
    const int rc = r.cellIndex(m.cellName(c));
    ASSERT_EQ(r.cellType(rc), m.cellType(c));
    EXPECT_TRUE(std::equal(m.cellNodes(c).begin(), m.cellNodes(c).end(), r.cellNodes(rc).begin()));
  }
  auto a = r.cellGroupNames(), b = m.cellGroupNames();
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  ASSERT_EQ(a, b);
  for (const auto& g : b) EXPECT_EQ(cellNames(r, r.cellGroup(g)), cellNames(m, m.cellGroup(g))) << g;
  EXPECT_EQ(r.nodeGroupNames(), std::vector<std::string>{"COINS"});
  EXPECT_EQ(r.nodeGroup("COINS"), (std::vector<int>{0, 1, 2, 3}));
}

TEST(Med, NodalFieldsPerInstant) {
  const Mesh m = readAsterMesh(kDir + "ssnp150b.mail");
  std::vector<FieldInstant> instants;
  for (int s = 1; s <= 2; ++s) {
    NodalField f{"DEPL", {"DX", "DY"}, {}};
    for (int i = 0; i < m.nodeCount(); ++i) f.values.insert(f.values.end(), {s * m.node(i)[0], s * m.node(i)[1]});
    instants.push_back({s, 0.5 * s, {f}});
  }
  writeMedResults(m, kOut + "mesh_results.med", instants);
  const NodalField f = readMedNodalField(kOut + "mesh_results.med", "DEPL", 2);
  EXPECT_EQ(f.components, (std::vector<std::string>{"DX", "DY"}));
  ASSERT_EQ(f.values.size(), 22u);
  EXPECT_DOUBLE_EQ(f.values[2 * 4], 2 * -0.5);  // N5 x = -0.5
  EXPECT_DOUBLE_EQ(f.values[2 * 4 + 1], 2 * -0.05);
  EXPECT_THROW(readMedNodalField(kOut + "mesh_results.med", "SIEF", 1), aster::Error);
}

TEST(Med, MalformedFileIsAnError) {
  std::ofstream(kOut + "mesh_bad.med") << "this is not an HDF5 file\n";
  EXPECT_THROW(readMedMesh(kOut + "mesh_bad.med"), aster::Error);
  EXPECT_THROW(readMedMesh(kOut + "no-such-file.med"), aster::Error);
  writeMedMesh(readAsterMesh(kDir + "ssnp150b.mail"), kOut + "mesh_named.med", "MA");
  EXPECT_THROW(readMedMesh(kOut + "mesh_named.med", "MB"), aster::Error);
  EXPECT_EQ(readMedMesh(kOut + "mesh_named.med", "MA").cellCount(), 6);
}

TEST(NodeOrdering, Conventions) {
  // 2D cells agree everywhere; MED's 3D cells are mirrored (code_aster's own table).
  for (auto c : {NodeConvention::Med, NodeConvention::Gmsh, NodeConvention::Vtk})
    for (auto t : {CellType::SEG3, CellType::TRIA6, CellType::QUAD8, CellType::QUAD9}) {
      const auto& p = asterFromForeign(c, t);
      for (std::size_t j = 0; j < p.size(); ++j) EXPECT_EQ(p[j], static_cast<int>(j));
    }
  EXPECT_EQ(asterFromForeign(NodeConvention::Med, CellType::HEXA8), (std::vector<int>{0, 3, 2, 1, 4, 7, 6, 5}));
  // gmsh TETRA10: edges 0-1, 1-2, 2-0, 3-0, 3-2, 3-1; code_aster: 0-1, 1-2, 2-0, 0-3, 1-3, 2-3.
  EXPECT_EQ(asterFromForeign(NodeConvention::Gmsh, CellType::TETRA10), (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 9, 8}));
  // VTK HEXA20: vertical edges after the top ones.
  const auto& v = asterFromForeign(NodeConvention::Vtk, CellType::HEXA20);
  EXPECT_EQ(v[12], 16);
  EXPECT_EQ(v[16], 12);
  EXPECT_THROW(asterFromForeign(NodeConvention::Gmsh, CellType::TRIA7), aster::Error);
  const std::vector<int> nodes{10, 11, 12, 13, 14, 15, 16, 17};
  EXPECT_EQ(toAsterOrder(NodeConvention::Med, CellType::HEXA8, fromAsterOrder(NodeConvention::Med, CellType::HEXA8, nodes)), nodes);
}

TEST(Vtk, VtuAndPvdFiles) {
  const Mesh m = readAsterMesh(kDir + "ssnp150b.mail");
  NodalField f{"DEPL", {"DX", "DY"}, std::vector<double>(22, 0.25)};
  writePvd(m, kOut + "mesh_out.pvd", {{1, 0.5, {f}}, {2, 1.0, {f}}});
  std::ifstream pvd(kOut + "mesh_out.pvd");
  std::stringstream s;
  s << pvd.rdbuf();
  EXPECT_NE(s.str().find("timestep=\"0.5\" part=\"0\" file=\"mesh_out_0.vtu\""), std::string::npos);
  EXPECT_NE(s.str().find("timestep=\"1\" part=\"0\" file=\"mesh_out_1.vtu\""), std::string::npos);
  std::ifstream vtu(kOut + "mesh_out_1.vtu");
  std::stringstream v;
  v << vtu.rdbuf();
  EXPECT_NE(v.str().find("NumberOfPoints=\"11\" NumberOfCells=\"6\""), std::string::npos);
  EXPECT_NE(v.str().find("0 3 2 1 9 8 7 6"), std::string::npos);  // the QUAD8, 0-based
  EXPECT_NE(v.str().find("\n23\n"), std::string::npos);            // VTK_QUADRATIC_QUAD
  EXPECT_NE(v.str().find("0.25 0.25 0"), std::string::npos);
  EXPECT_THROW(writeVtu(m, kOut + "mesh_bad.vtu", {{"X", {"A"}, {1.0}}}), aster::Error);
}

TEST(Vtk, ContactMultiplierIsItsOwnScalar) {
  const Mesh m = readAsterMesh(kDir + "ssnp150b.mail");
  NodalField f{"DEPL", {"DX", "DY", "LAGS_C"}, {}};
  for (int n = 0; n < m.nodeCount(); ++n) f.values.insert(f.values.end(), {0.25, -0.5, 7.0});
  writeVtu(m, kOut + "mesh_lags.vtu", {f});
  std::ifstream vtu(kOut + "mesh_lags.vtu");
  std::stringstream v;
  v << vtu.rdbuf();
  const std::string text = v.str();
  EXPECT_NE(text.find("Name=\"DEPL\" NumberOfComponents=\"3\" ComponentName0=\"DX\" ComponentName1=\"DY\" "
                      "format"),
            std::string::npos);
  EXPECT_NE(text.find("0.25 -0.5 0 \n"), std::string::npos);  // the vector: z = 0, not LAGS_C
  EXPECT_EQ(text.find("0.25 -0.5 7"), std::string::npos);
  EXPECT_NE(text.find("Name=\"DEPL_LAGS_C\" NumberOfComponents=\"1\" ComponentName0=\"LAGS_C\" format=\"ascii\">\n7 \n7 \n"),
            std::string::npos);
}

TEST(Orientation, ReversedBoundarySegmentsAreTurnedOutward) {
  Mesh m = readAsterMesh(kDir + "ssnp150b.mail");
  // In ssnp150b.mail, M1 (x=0) goes up, M2 (y=1) goes right, M3 (x=1) goes down, M4 (y=0) goes left:
  // all clockwise, i.e. inward normals, for the counterclockwise QUAD8.
  const std::vector<int> segs = unionOfCellGroups(m, {"GAUCHE", "HAUT", "DROITE", "BAS", "MAITRE"});
  EXPECT_EQ(orientBoundarySegments(m, segs), 4);
  const Eigen::Vector3d centre(0.5, 0.5, 0);
  for (const char* g : {"GAUCHE", "HAUT", "DROITE", "BAS"}) {
    const auto n = m.cellNodes(m.cellGroup(g)[0]);
    const Eigen::Vector3d a = m.node(n[0]), b = m.node(n[1]), mid = m.node(n[2]);
    const Eigen::Vector3d normal(b[1] - a[1], -(b[0] - a[0]), 0);
    EXPECT_GT(normal.dot(mid - centre), 0) << g;
    EXPECT_NEAR((mid - 0.5 * (a + b)).norm(), 0, 1e-15) << g;  // middle node kept in the middle
  }
  // MAITRE touches no 2D cell: alone in its chain, it stays as it is; a second call changes nothing.
  EXPECT_EQ(m.nodeName(m.cellNodes(m.cellGroup("MAITRE")[0])[0]), "N6");
  EXPECT_EQ(orientBoundarySegments(m, segs), 0);

  // A free chain of three SEG2 with the middle one reversed follows its first segment.
  Mesh c;
  for (int i = 0; i < 4; ++i) c.addNode(Eigen::Vector3d(i, 0, 0));
  c.addCell(CellType::SEG2, {0, 1});
  c.addCell(CellType::SEG2, {2, 1});
  c.addCell(CellType::SEG2, {2, 3});
  EXPECT_EQ(orientBoundarySegments(c, {0, 1, 2}), 1);
  EXPECT_EQ(c.cellNodes(1)[0], 1);
  EXPECT_THROW(orientBoundarySegments(m, m.cellGroup("SURFACE")), aster::Error);
}

TEST(Groups, UnionIntersectionDifference) {
  const Mesh m = readAsterMesh(kDir + "ssnp150b.mail");
  const auto u = unionOfCellGroups(m, {"BAS", "HAUT", "BAS"});
  EXPECT_EQ(cellNames(m, u), (std::vector<std::string>{"M2", "M4"}));
  Mesh n = m;
  n.addCellGroup("BH", u);
  EXPECT_EQ(cellNames(n, intersectionOfCellGroups(n, {"BH", "HAUT"})), std::vector<std::string>{"M2"});
  EXPECT_EQ(cellNames(n, differenceOfCellGroups(n, {"BH", "HAUT"})), std::vector<std::string>{"M4"});
  EXPECT_EQ(nodesOfCellGroups(n, {"BH"}).size(), 6u);
  EXPECT_THROW(unionOfCellGroups(n, {"BAS", "HUAT"}), aster::Error);
  EXPECT_THROW(n.addCellGroup("BH", {}), aster::Error);
}

TEST(Groups, NoeudOrdoOnAShuffledChain) {
  // BAS of the twice-refined ssnp150b: 4 SEG3 on y = 0, given shuffled and with mixed directions.
  Mesh m = readAsterMesh(kDir + "ssnp150b.mail");
  m = refineUniformly(m, m.cellGroup("SURFACE"));
  m = refineUniformly(m, m.cellGroup("SURFACE"));
  std::vector<int> bas = m.cellGroup("BAS");
  ASSERT_EQ(bas.size(), 4u);
  std::swap(bas[0], bas[2]);
  std::swap(bas[1], bas[3]);
  reverseSegment(m, bas[1]);
  // Walking in the direction of the first cell given: M4 goes from x=1 towards x=0.
  const int first = bas[0];
  const bool firstGoesLeft = m.node(m.cellNodes(first)[1])[0] < m.node(m.cellNodes(first)[0])[0];
  const auto nodes = orderedChainNodes(m, bas);
  ASSERT_EQ(nodes.size(), 9u);
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const double x = firstGoesLeft ? 1.0 - 0.125 * k : 0.125 * k;
    EXPECT_NEAR(m.node(nodes[k])[0], x, 1e-15) << k;
    EXPECT_NEAR(m.node(nodes[k])[1], 0.0, 1e-15);
  }
  // From the other end on request.
  const auto back = orderedChainNodes(m, bas, nodes.back());
  EXPECT_TRUE(std::equal(back.begin(), back.end(), nodes.rbegin()));
  EXPECT_THROW(orderedChainNodes(m, bas, nodes[1]), aster::Error);
  // Not one open chain: two pieces, a closed loop, a 2D cell.
  EXPECT_THROW(orderedChainNodes(m, {bas[0], bas[2]}), aster::Error);
  EXPECT_THROW(orderedChainNodes(m, unionOfCellGroups(m, {"BAS", "DROITE", "HAUT", "GAUCHE"})), aster::Error);
  EXPECT_THROW(orderedChainNodes(m, m.cellGroup("SURFACE")), aster::Error);
}
