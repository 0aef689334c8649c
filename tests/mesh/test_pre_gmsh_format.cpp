// gmsh MSH 1 and MSH 2 ASCII read as code_aster's PRE_GMSH converts them.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "mesh/io/pre_gmsh_format.hpp"

using namespace aster::mesh;

namespace {

std::string errorOf(const std::string& text) {
  try {
    parseGmshAsPreGmsh(text, "bad.msh");
  } catch (const aster::Error& e) {
    return e.what();
  }
  return "no error";
}

std::vector<std::string> nodeNames(const Mesh& m, int cell) {
  std::vector<std::string> names;
  for (int n : m.cellNodes(cell)) names.push_back(m.nodeName(n));
  return names;
}

// Two QUAD4 (physical 1) of the 2 x 1 rectangle, its left edge (physical 2), a
// POI1 at node 30 (physical 4), an element of physical 0; node numbers are not
// consecutive and node 99 belongs to no element.
const std::string kNodes1 =
    "$NOD\n7\n10 0 0 0\n20 1 0 0\n30 2 0 0\n40 0 1 0\n50 1 1 0\n60 2 1 0.5\n99 9 9 9\n$ENDNOD\n";
const std::string kMsh1 = kNodes1 +
                          "$ELM\n6\n"
                          "7 3 1 11 4 10 20 50 40\n"
                          "8 1 2 12 2 40 10\n"
                          "9 15 4 13 1 30\n"
                          "3 3 1 11 4 20 30 60 50\n"
                          "5 1 0 14 2 30 60\n"
                          "6 1 2 12 2\n 10 40\n"  // an element may wrap
                          "$ENDELM\n";

void expectTheRectangle(const Mesh& m) {
  EXPECT_EQ(m.spaceDimension(), 3);
  ASSERT_EQ(m.nodeCount(), 6);  // node 99 is dropped
  EXPECT_EQ(m.nodeName(0), "N10");
  EXPECT_EQ(m.node(m.nodeIndex("N60")), Eigen::Vector3d(2, 1, 0.5));
  ASSERT_EQ(m.cellCount(), 6);
  // By gmsh type (1 SEG2, 3 QUAD4, 15 POI1), file order within a type.
  const std::vector<std::string> names{"M8", "M5", "M6", "M7", "M3", "M9"};
  for (int c = 0; c < 6; ++c) EXPECT_EQ(m.cellName(c), names[c]);
  EXPECT_EQ(m.cellType(m.cellIndex("M7")), CellType::QUAD4);
  EXPECT_EQ(nodeNames(m, m.cellIndex("M7")), (std::vector<std::string>{"N10", "N20", "N50", "N40"}));
  EXPECT_EQ(nodeNames(m, m.cellIndex("M6")), (std::vector<std::string>{"N10", "N40"}));
  // Groups GM<physical> in order of first appearance; none for physical 0.
  EXPECT_EQ(m.cellGroupNames(), (std::vector<std::string>{"GM1", "GM2", "GM4"}));
  EXPECT_EQ(m.cellGroup("GM1"), (std::vector<int>{m.cellIndex("M7"), m.cellIndex("M3")}));
  EXPECT_EQ(m.cellGroup("GM2"), (std::vector<int>{m.cellIndex("M8"), m.cellIndex("M6")}));
  // A group of one POI1 is also a group of nodes.
  EXPECT_EQ(m.nodeGroupNames(), std::vector<std::string>{"GM4"});
  EXPECT_EQ(m.nodeGroup("GM4"), std::vector<int>{m.nodeIndex("N30")});
}

}  // namespace

TEST(PreGmshFormat, Msh1AsPreGmshConvertsIt) { expectTheRectangle(parseGmshAsPreGmsh(kMsh1, "rect.msh")); }

TEST(PreGmshFormat, Msh2AsciiGivesTheSameMesh) {
  const std::string msh2 =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
      "$PhysicalNames\n1\n2 1 \"PLATE\"\n$EndPhysicalNames\n"  // names are not used
      "$Nodes\n7\n10 0 0 0\n20 1 0 0\n30 2 0 0\n40 0 1 0\n50 1 1 0\n60 2 1 0.5\n99 9 9 9\n$EndNodes\n"
      "$Elements\n6\n"
      "7 3 2 1 11 10 20 50 40\n"
      "8 1 2 2 12 40 10\n"
      "9 15 3 4 13 0 30\n"
      "3 3 2 1 11 20 30 60 50\n"
      "5 1 0 30 60\n"
      "6 1 2 2 12 10 40\n"
      "$EndElements\n";
  expectTheRectangle(parseGmshAsPreGmsh(msh2, "rect2.msh"));
}

// gmsh's node order becomes code_aster's: the TETRA10 swaps its last two
// mid-edge nodes (gmsh: edges 0-1 1-2 2-0 0-3 2-3 1-3; code_aster: ... 1-3 2-3);
// QUAD9 (type 10) and the 14-node pyramid (type 14) lose their centre node.
TEST(PreGmshFormat, NodeOrderAndCentreNodesAsCodeAster) {
  std::string nodes = "$NOD\n14\n";
  for (int n = 1; n <= 14; ++n) nodes += std::to_string(n) + " " + std::to_string(n) + " 0 0\n";
  const Mesh m = parseGmshAsPreGmsh(nodes +
                                        "$ENDNOD\n$ELM\n3\n"
                                        "1 11 1 1 10 1 2 3 4 5 6 7 8 9 10\n"
                                        "2 10 1 1 9 1 2 3 4 5 6 7 8 9\n"
                                        "3 14 1 1 14 1 2 3 4 5 6 7 8 9 10 11 12 13 14\n"
                                        "$ENDELM\n",
                                    "order.msh");
  const int tet = m.cellIndex("M1"), quad = m.cellIndex("M2"), pyram = m.cellIndex("M3");
  EXPECT_EQ(m.cellType(tet), CellType::TETRA10);
  EXPECT_EQ(nodeNames(m, tet),
            (std::vector<std::string>{"N1", "N2", "N3", "N4", "N5", "N6", "N7", "N8", "N10", "N9"}));
  EXPECT_EQ(m.cellType(quad), CellType::QUAD8);
  EXPECT_EQ(nodeNames(m, quad), (std::vector<std::string>{"N1", "N2", "N3", "N4", "N5", "N6", "N7", "N8"}));
  EXPECT_EQ(m.cellType(pyram), CellType::PYRAM13);
  EXPECT_EQ(m.nodeCount(), 13);  // N14, the pyramid's centre, is used by no code_aster cell
  EXPECT_LT(m.findNode("N14"), 0);
}

TEST(PreGmshFormat, MalformedFilesNameLineAndWhat) {
  auto has = [](const std::string& msg, const std::string& part) { return msg.find(part) != std::string::npos; };
  std::string m = errorOf(kNodes1 + "$ELM\n1\n1 93 1 1 1 10\n$ENDELM\n");
  EXPECT_TRUE(has(m, "bad.msh:13: element 1 has gmsh type 93, which PRE_GMSH does not convert")) << m;
  m = errorOf(kNodes1 + "$ELM\n1\n1 1 1 1 2 10 77\n$ENDELM\n");
  EXPECT_TRUE(has(m, "bad.msh:13: node 77 of element 1 is not defined in the nodes section")) << m;
  m = errorOf(kNodes1 + "$ELM\n1\n1 2 1 1 4 10 20 30 40\n$ENDELM\n");
  EXPECT_TRUE(has(m, "bad.msh:13: element 1 of gmsh type 2 has 4 nodes, expected 3")) << m;
  m = errorOf(kNodes1 + "$ELM\n2\n1 15 1 1 1 10\n1 15 1 1 1 20\n$ENDELM\n");
  EXPECT_TRUE(has(m, "bad.msh:14: element 1 is defined twice (first at line 13)")) << m;
  m = errorOf("$NOD\n2\n1 0 0 0\n1 1 0 0\n$ENDNOD\n");
  EXPECT_TRUE(has(m, "bad.msh:4: node 1 is defined twice")) << m;
  m = errorOf("$NOD\n2\n1 0 0 0\n2 1 zero 0\n$ENDNOD\n");
  EXPECT_TRUE(has(m, "bad.msh:4: expected the y of node 2 (a number), found 'zero'")) << m;
  m = errorOf(kNodes1 + "$ELM\n2\n1 15 1 1 1 10\n");
  EXPECT_TRUE(has(m, "the file ends where an element number was expected (truncated file?)")) << m;
  m = errorOf("$NOD\n1\n1 0 0 0\n$ELM\n");
  EXPECT_TRUE(has(m, "bad.msh:4: expected $ENDNOD, found '$ELM'")) << m;
  m = errorOf("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n");
  EXPECT_TRUE(has(m, "bad.msh:2: MSH version 4.1: PRE_GMSH reads MSH 1 and 2")) << m;
  m = errorOf("$MeshFormat\n2.2 1 8\n");
  EXPECT_TRUE(has(m, "bad.msh:2: a binary MSH file: PRE_GMSH reads ASCII files")) << m;
  m = errorOf("solid cube\n");
  EXPECT_TRUE(has(m, "bad.msh:1: expected $NOD or $MeshFormat, found 'solid'")) << m;
  m = errorOf("");
  EXPECT_TRUE(has(m, "bad.msh:1: the file is empty")) << m;
  m = errorOf(kNodes1 + "$ELM\n1\n1 15 1000000 1 1 10\n$ENDELM\n");
  EXPECT_TRUE(has(m, "expected a tag from 0 to 999999")) << m;
}

// LIRE_MAILLAGE{FORMAT='GMSH'} hands MSH 1, 2.0 and 2.1 to this reader, 2.2 and 4.x to gmsh's library.
TEST(PreGmshFormat, WhichFilesLireMaillageReadsAsPreGmsh) {
  const std::string dir = ::testing::TempDir();
  auto fileWith = [&](const std::string& name, const std::string& text) {
    const std::string path = dir + "/" + name;
    std::ofstream(path) << text;
    return path;
  };
  EXPECT_TRUE(isPreGmshOnlyFile(fileWith("v1.msh", "$NOD\n1\n")));
  EXPECT_TRUE(isPreGmshOnlyFile(fileWith("v20.msh", "$MeshFormat\n2 0 8\n")));
  EXPECT_TRUE(isPreGmshOnlyFile(fileWith("v21.msh", "$MeshFormat\n2.1 0 8\n")));
  EXPECT_FALSE(isPreGmshOnlyFile(fileWith("v22.msh", "$MeshFormat\n2.2 0 8\n")));
  EXPECT_FALSE(isPreGmshOnlyFile(fileWith("v41.msh", "$MeshFormat\n4.1 0 8\n")));
  EXPECT_FALSE(isPreGmshOnlyFile(fileWith("empty.msh", "")));
  EXPECT_FALSE(isPreGmshOnlyFile(dir + "/absent.msh"));
}
