// Malformed GMSH and MED files: each message names the file, the line (or the
// MED object) and what was expected. The files are written by hand, so the
// line of each fault is known.
#include <gtest/gtest.h>
#include <med.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.hpp"
#include "mesh/io/gmsh_format.hpp"
#include "mesh/io/med_format.hpp"
#include "mesh/io/msh_check.hpp"

using namespace aster::mesh;
using namespace std::string_literals;

namespace {

const std::string kTmp = std::string(ASTER_BINARY_DIR) + "/mesh_file_errors/";

std::string writeFile(const std::string& name, const std::string& text) {
  std::filesystem::create_directories(kTmp);
  const std::string path = kTmp + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

template <class F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const aster::Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "no aster::Error";
  return "";
}

std::string gmshError(const std::string& path) {
  return errorOf([&] { readGmshMesh(path); });
}
std::string medError(const std::string& path, const std::string& mesh = "") {
  return errorOf([&] { readMedMesh(path, mesh); });
}

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// Lines 1-3.
const std::string kHeader22 = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
// Lines 4-10: the unit square's corners.
const std::string kNodes22 = "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndNodes\n";
// Lines 11-15 when after the two above: a SEG2 (physical 1) and a QUAD4 (physical 2).
const std::string kElements22 = "$Elements\n2\n1 1 2 1 1 1 2\n2 3 2 2 2 1 2 3 4\n$EndElements\n";

const std::string kSupported =
    "15 (POI1), 1 (SEG2), 8 (SEG3), 26 (SEG4), 2 (TRIA3), 9 (TRIA6), 3 (QUAD4), 16 (QUAD8), 10 (QUAD9), "
    "4 (TETRA4), 11 (TETRA10), 6 (PENTA6), 18 (PENTA15), 13 (PENTA18), 7 (PYRAM5), 19 (PYRAM13), 5 (HEXA8), "
    "17 (HEXA20), 12 (HEXA27)";

// MSH 4.1, lines 1-3 header, 4-15 nodes, 16-20 elements: one QUAD4 on the unit square.
std::string file41(const std::string& nodesHeader = "1 4 1 4", const std::string& nodeBlock = "2 1 0 4",
                   const std::string& lastCoordinates = "0 1 0\n", const std::string& elementBlock = "2 1 3 1",
                   const std::string& element = "1 1 2 3 4", const std::string& afterBlock = "") {
  return "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n" + nodesHeader + "\n" + nodeBlock +
         "\n1\n2\n3\n4\n0 0 0\n1 0 0\n1 1 0\n" + lastCoordinates + "$EndNodes\n$Elements\n1 1 1 1\n" + elementBlock +
         "\n" + element + "\n" + afterBlock + "$EndElements\n";
}

}  // namespace

TEST(MshCheck, WellFormedAsciiFilesOfEachVersionAreRead) {
  const Mesh m22 = readGmshMesh(writeFile("ok22.msh", kHeader22 + kNodes22 + kElements22));
  EXPECT_EQ(m22.cellCount(), 2);
  EXPECT_EQ(m22.countCells(CellType::SEG2), 1);
  EXPECT_EQ(m22.countCells(CellType::QUAD4), 1);
  EXPECT_EQ(m22.cellGroup("GM1").size(), 1u);
  EXPECT_EQ(m22.nodeGroup("GM2").size(), 4u);

  const Mesh m41 = readGmshMesh(writeFile("ok41.msh", file41()));
  ASSERT_EQ(m41.cellCount(), 1);
  EXPECT_EQ(m41.cellType(0), CellType::QUAD4);
  EXPECT_EQ(m41.nodeCount(), 4);
  EXPECT_EQ(m41.node(m41.nodeIndex("N3")), Eigen::Vector3d(1, 1, 0));

  // MSH 4.0: "<entity> <dim> <parametric> <count>" blocks, nodes "<tag> <x> <y> <z>".
  const Mesh m40 = readGmshMesh(
      writeFile("ok40.msh",
                "$MeshFormat\n4 0 8\n$EndMeshFormat\n$Nodes\n1 3\n1 2 0 3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n"
                "$Elements\n1 1\n1 2 2 1\n7 1 2 3\n$EndElements\n"));
  ASSERT_EQ(m40.cellCount(), 1);
  EXPECT_EQ(m40.cellType(0), CellType::TRIA3);
  EXPECT_EQ(m40.cellName(0), "M7");

  // Windows line ends, blank lines and $Comments holding a '$' line are accepted.
  std::string crlf = kHeader22 + "$Comments\n$not a section\n$EndComments\n\n" + kNodes22 + kElements22;
  for (std::size_t p = 0; (p = crlf.find('\n', p)) != std::string::npos; p += 2) crlf.insert(p, "\r");
  EXPECT_EQ(readGmshMesh(writeFile("crlf.msh", crlf)).cellCount(), 2);
}

TEST(MshCheck, EmptyFile) {
  const std::string path = writeFile("empty.msh", "\n   \n\n");
  EXPECT_EQ(gmshError(path),
            path + ": the file is empty (expected a gmsh .msh file, version 2.2 or 4.1, starting with $MeshFormat)");
}

TEST(MshCheck, HeaderErrorsGiveTheLineAndWhatWasExpected) {
  // MSH 1 (or anything else) on the first non-empty line.
  std::string path = writeFile("msh1.msh", "\n$NOD\n1\n1 0 0 0\n$ENDNOD\n");
  EXPECT_EQ(gmshError(path),
            path + ":2: found '$NOD' (expected $MeshFormat, the first line of a gmsh .msh file, version 2.2 or 4.1)");
  // gmsh wants $MeshFormat at the very start of the file.
  path = writeFile("blank_first.msh", "\n\n" + kHeader22 + kNodes22 + kElements22);
  EXPECT_EQ(gmshError(path), path +
                                 ":1: found an empty line (expected $MeshFormat on the first line of a gmsh .msh "
                                 "file, version 2.2 or 4.1, not on line 3)");
  path = writeFile("indented.msh", "  " + kHeader22 + kNodes22 + kElements22);
  EXPECT_EQ(gmshError(path), path +
                                 ":1: found blanks before $MeshFormat (expected $MeshFormat at the start of the "
                                 "first line of a gmsh .msh file, version 2.2 or 4.1)");
  path = writeFile("only_format.msh", "$MeshFormat\n");
  EXPECT_EQ(gmshError(path), path +
                                 ":1: the file ends after $MeshFormat (expected '<version> <file-type> <data-size>', "
                                 "e.g. '4.1 0 8')");
  path = writeFile("short_header.msh", "$MeshFormat\n2.2 0\n$EndMeshFormat\n" + kNodes22 + kElements22);
  EXPECT_EQ(gmshError(path), path +
                                 ":2: found '2.2 0' after $MeshFormat (expected '<version> <file-type> <data-size>', "
                                 "e.g. '4.1 0 8')");
  path = writeFile("v3.msh", "$MeshFormat\n3.0 0 8\n$EndMeshFormat\n" + kNodes22 + kElements22);
  EXPECT_EQ(gmshError(path), path + ":2: MSH version 3.0 is not supported (expected 2.2, 4.0 or 4.1)");
  path = writeFile("type2.msh", "$MeshFormat\n2.2 2 8\n$EndMeshFormat\n" + kNodes22 + kElements22);
  EXPECT_EQ(gmshError(path), path + ":2: file type 2 (expected 0 for ASCII or 1 for binary)");
  path = writeFile("size4.msh", "$MeshFormat\n4.1 1 4\n");
  EXPECT_EQ(gmshError(path), path + ":2: data size 4 (expected 8, the size of a double)");
  // A binary file gets the same header check.
  path = writeFile("bin_v5.msh", "$MeshFormat\n5 1 8\n\x01\x00\x00\x00\n$EndMeshFormat\n"s);
  EXPECT_EQ(gmshError(path), path + ":2: MSH version 5 is not supported (expected 2.2, 4.0 or 4.1)");
}

TEST(MshCheck, SectionLeftOpenOrClosedWrongly) {
  // Truncated in the middle of an element line: the open section is reported, not the cut line.
  std::string path = writeFile("truncated.msh", kHeader22 + kNodes22 + "$Elements\n2\n1 1 2 1 1 1 2\n2 3 2");
  EXPECT_EQ(gmshError(path), path +
                                 ":11: section $Elements is not closed: the file ends at line 14 (expected "
                                 "$EndElements; truncated file?)");
  path = writeFile("truncated_header.msh", "$MeshFormat\n2.2 0 8\n");
  EXPECT_EQ(gmshError(path), path +
                                 ":1: section $MeshFormat is not closed: the file ends at line 2 (expected "
                                 "$EndMeshFormat; truncated file?)");
  path = writeFile("wrong_end.msh", kHeader22 + "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndElements\n");
  EXPECT_EQ(gmshError(path),
            path + ":10: found $EndElements inside section $Nodes opened at line 4 (expected $EndNodes)");
  path = writeFile("nested.msh", kHeader22 + "$Nodes\n4\n1 0 0 0\n2 1 0 0\n" + kElements22);
  EXPECT_EQ(gmshError(path), path +
                                 ":8: found $Elements inside section $Nodes opened at line 4 (expected $EndNodes "
                                 "first; truncated section?)");
  path = writeFile("stray_end.msh", kHeader22 + "$EndNodes\n" + kNodes22 + kElements22);
  EXPECT_EQ(gmshError(path), path + ":4: found $EndNodes outside any section (expected $Nodes before it)");
}

// gmsh reads the lines between sections with fgets, in pieces of at most 254
// or 1022 bytes, and opens a section at each piece that starts with "$<name>",
// comparing the beginning of the name only.
TEST(MshCheck, LinesAsGmshReadsThem) {
  // A header line longer than gmsh's buffer: its second piece would be the version line.
  std::string path = writeFile("long_header.msh", "$MeshFormat" + std::string(244, ' ') + "2.2 0 8" + file41().substr(11));
  EXPECT_EQ(gmshError(path), path + ":1: found a header line of 262 bytes (expected at most 254)");

  // A '$' inside a long line starts a piece that gmsh reads as a section marker.
  path = writeFile("long_line.msh", kHeader22 + std::string(300, 'x') + "$Nodes\n" + kNodes22 + kElements22);
  EXPECT_EQ(gmshError(path), path +
                                 ":4: found a line of 306 bytes with a '$' at column 301 (expected '$' only at the "
                                 "start of a line longer than 254 bytes: gmsh reads such a line in pieces, and a "
                                 "piece starting with '$' would open a section)");

  // gmsh's MSH 2 reader opens a section at every '$' line, also in $Comments.
  path = writeFile("comment_nodes.msh",
                   kHeader22 + "$Comments\n$Nodes\n1\n1 0 0 nan\n$EndComments\n" + kNodes22 + kElements22);
  EXPECT_EQ(gmshError(path), path +
                                 ":5: found $Nodes inside section $Comments opened at line 4 (expected $EndComments "
                                 "first: gmsh reads $Nodes there)");

  // "$NodesX" is read by gmsh as $Nodes, "$NOD" as the nodes of MSH 1.
  path = writeFile("nodes_x.msh", kHeader22 + "$NodesX\n1\n1 0 0 nan\n$EndNodesX\n" + kNodes22 + kElements22);
  EXPECT_EQ(gmshError(path), path +
                                 ":4: found $NodesX, which gmsh reads as section $Nodes (it compares the beginnings "
                                 "of section names; expected $Nodes)");
  // A second $MeshFormat: gmsh reads the file type again (here: the rest is binary).
  path = writeFile("second_format.msh", kHeader22 + "$MeshFormat\n2.2 1 8\n$EndMeshFormat\n" + kNodes22 + kElements22);
  EXPECT_EQ(gmshError(path), path +
                                 ":4: found a second section $MeshFormat (expected one: gmsh would read the file type "
                                 "again, and the rest of the file as binary if it says so)");
  path = writeFile("nod.msh", kHeader22 + "$NOD\n1\n1 0 0 nan\n$ENDNOD\n" + kNodes22 + kElements22);
  EXPECT_EQ(gmshError(path), path +
                                 ":4: found $NOD, which gmsh reads as section $Nodes (it compares the beginnings of "
                                 "section names; expected $Nodes)");
}

// Data sections are read by gmsh's data reader, which trusts the sizes it reads:
// it sizes a matrix of $InterpolationScheme as announced, makes an object per time
// step number up to the one read and sizes its tables by the largest entity tag.
TEST(MshCheck, DataSectionsWithinWhatTheFileHolds) {
  const auto checkError = [](const std::string& path) { return errorOf([&] { checkMshFile(path); }); };
  const std::string data = "$NodeData\n1\n\"u\"\n1\n0\n3\n";  // lines 21-26; then the integer tags
  EXPECT_EQ(readGmshMesh(writeFile("data_ok.msh", file41() + data + "0\n1\n2\n1 0.5\n4 -1\n$EndNodeData\n")).cellCount(), 1);

  std::string path = writeFile("data_tag.msh", file41() + data + "0\n1\n1\n2000000000 0\n$EndNodeData\n");
  EXPECT_EQ(checkError(path), path +
                                  ":30: found '2000000000 0' in $NodeData (line 21) (expected a node tag 0 to 4, the "
                                  "largest of the file so far, then its values)");
  path = writeFile("data_step.msh", file41() + data + "2000000000\n1\n1\n1 0\n$EndNodeData\n");
  EXPECT_EQ(checkError(path), path + ":29: time step 2000000000 in $NodeData (line 21) (expected 0 to 100000)");
  path = writeFile("data_short.msh", file41() + data + "0\n3\n2\n1 0 0 0\n2 0 0\n$EndNodeData\n");
  EXPECT_EQ(checkError(path), path +
                                  ":31: found '2 0 0' in $NodeData (line 21) (expected 3 numbers after the node tag)");

  path = writeFile("scheme.msh", file41() + "$InterpolationScheme\n\"x\"\n1\n3 1\n100000 100000\n$EndInterpolationScheme\n" +
                                     data + "0\n1\n1\n1 0\n$EndNodeData\n");
  EXPECT_EQ(checkError(path), path +
                                  ":26: found $EndInterpolationScheme (section at line 21): a matrix of 100000 x "
                                  "100000 with 0 numbers left (expected the numbers of the matrices announced)");
}

// ASCII sections gmsh reads trusting their sizes: $Entities (a buffer of 128 bytes
// per entity announced) is checked by its number of lines, the others are refused.
TEST(MshCheck, AsciiSectionsGmshSizesByTheirCounts) {
  const std::string header = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  std::string path = writeFile("entities_count.msh", header + "$Entities\n100000000 0 0 0\n1 0 0 0 0\n$EndEntities\n" +
                                                         file41().substr(header.size()));
  EXPECT_EQ(gmshError(path), path + ":7: found $EndEntities after 1 entity line (expected 100000000, as announced at "
                                    "line 5)");
  path = writeFile("periodic41.msh", file41() + "$Periodic\n1\n1 1 1\n1000000000000\n$EndPeriodic\n");
  EXPECT_EQ(gmshError(path), path + ":21: found $Periodic, a section aster-lite does not read and in which gmsh trusts "
                                    "the sizes it reads (expected $PhysicalNames, $Entities, $Nodes, $Elements and "
                                    "data sections only)");
}

// MSH 4.0: gmsh allocates the announced number of nodes and elements at once.
TEST(MshCheck, Version40Blocks) {
  const std::string header = "$MeshFormat\n4 0 8\n$EndMeshFormat\n";
  const std::string elements = "$Elements\n1 1\n1 2 2 1\n7 1 2 3\n$EndElements\n";
  std::string path = writeFile("v40_count.msh", header + "$Nodes\n1 3000000000\n1 2 0 3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n"
                                                 "$EndNodes\n" + elements);
  EXPECT_EQ(gmshError(path), path + ":10: found $EndNodes: the blocks hold 3 nodes (expected 3000000000, as announced at "
                                    "line 5)");
  path = writeFile("v40_node.msh", header + "$Nodes\n1 3\n1 2 0 3\n1 0 0 0\n2 1 0\n3 0 1 0\n$EndNodes\n" + elements);
  EXPECT_EQ(gmshError(path), path + ":8: found '2 1 0' (expected a node line '<tag> <x> <y> <z>', block at line 6)");
  path = writeFile("v40_element.msh",
                   header + "$Nodes\n1 3\n1 2 0 3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n$Elements\n1 1\n1 2 2 1\n7 1 2 4\n$EndElements\n");
  EXPECT_EQ(gmshError(path), path + ":14: element 7 refers to node 4, which is not defined (expected a node of the "
                                    "$Nodes section at line 4)");
}

TEST(MshCheck, Version22CountsAndLines) {
  std::string path = writeFile("few_nodes.msh",
                               kHeader22 + "$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndNodes\n" + kElements22);
  EXPECT_EQ(gmshError(path), path + ":10: found $EndNodes after 4 node lines (expected 5, as announced at line 5)");
  path = writeFile("many_nodes.msh",
                   kHeader22 + "$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndNodes\n" + kElements22);
  EXPECT_EQ(gmshError(path),
            path + ":9: found '4 0 1 0', one node line more than the 3 announced at line 5 (expected $EndNodes)");
  path = writeFile("count_word.msh", kHeader22 + "$Nodes\nfour\n1 0 0 0\n$EndNodes\n");
  EXPECT_EQ(gmshError(path), path + ":5: found 'four' after $Nodes (expected the number of nodes)");
  path = writeFile("garbled_node.msh",
                   kHeader22 + "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 one 0\n4 0 1 0\n$EndNodes\n" + kElements22);
  EXPECT_EQ(gmshError(path), path + ":8: found '3 1 one 0' (expected a node line '<tag> <x> <y> <z>')");
  // A control byte is shown escaped.
  path = writeFile("binary_node.msh",
                   kHeader22 + "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 \x01 0\n4 0 1 0\n$EndNodes\n" + kElements22);
  EXPECT_EQ(gmshError(path), path + ":8: found '3 1 \\x01 0' (expected a node line '<tag> <x> <y> <z>')");
  path = writeFile("few_elements.msh", kHeader22 + kNodes22 +
                                           "$Elements\n3\n1 1 2 1 1 1 2\n2 3 2 2 2 1 2 3 4\n"
                                           "$EndElements\n");
  EXPECT_EQ(gmshError(path),
            path + ":15: found $EndElements after 2 element lines (expected 3, as announced at line 12)");
  path = writeFile("garbled_element.msh",
                   kHeader22 + kNodes22 + "$Elements\n2\n1 1 2 1 1 1 2\n2 3 2 2 2 1 2 3 x\n$EndElements\n");
  EXPECT_EQ(gmshError(path), path +
                                 ":14: found '2 3 2 2 2 1 2 3 x' (expected an element line '<tag> <type> <number of "
                                 "tags> <tags> <nodes>')");
  path = writeFile("quad_3_nodes.msh",
                   kHeader22 + kNodes22 + "$Elements\n2\n1 1 2 1 1 1 2\n2 3 2 2 2 1 2 3\n$EndElements\n");
  EXPECT_EQ(gmshError(path), path + ":14: element 2 (gmsh type 3, QUAD4) has 3 nodes after its 2 tags (expected 4)");
  path =
      writeFile("type93.msh", kHeader22 + kNodes22 + "$Elements\n2\n1 1 2 1 1 1 2\n2 93 2 2 2 1 2 3 4\n$EndElements\n");
  EXPECT_EQ(gmshError(path), path +
                                 ":14: element 2 has gmsh type 93, which aster-lite does not read (expected one of "
                                 "the gmsh types " +
                                 kSupported + ")");
  path =
      writeFile("node40.msh", kHeader22 + kNodes22 + "$Elements\n2\n1 1 2 1 1 1 2\n2 3 2 2 2 1 2 3 40\n$EndElements\n");
  EXPECT_EQ(gmshError(path), path +
                                 ":14: element 2 refers to node 40, which is not defined (expected a node of the "
                                 "$Nodes section at line 4)");
}

TEST(MshCheck, Version41Blocks) {
  std::string path = writeFile("v41_type93.msh", file41("1 4 1 4", "2 1 0 4", "0 1 0\n", "2 1 93 1"));
  EXPECT_EQ(gmshError(path), path +
                                 ":18: the elements of entity 1 (dimension 2) have gmsh type 93, which aster-lite "
                                 "does not read (expected one of the gmsh types " +
                                 kSupported + ")");
  path = writeFile("v41_short_block.msh", file41("1 4 1 4", "2 1 0 4", ""));
  EXPECT_EQ(gmshError(path), path + ":14: found $EndNodes inside the node block at line 6 (expected 1 more line)");
  path = writeFile("v41_total.msh", file41("1 5 1 5"));
  EXPECT_EQ(gmshError(path),
            path + ":15: found $EndNodes: the blocks hold 4 nodes (expected 5, as announced at line 5)");
  path = writeFile("v41_blocks.msh", file41("2 4 1 4"));
  EXPECT_EQ(gmshError(path), path + ":15: found $EndNodes after 1 node block (expected 2, as announced at line 5)");
  path = writeFile("v41_coordinates.msh", file41("1 4 1 4", "2 1 0 4", "0 1\n"));
  EXPECT_EQ(gmshError(path), path +
                                 ":14: found '0 1' (expected 3 numbers: the coordinates of a node of the block at "
                                 "line 6)");
  path = writeFile("v41_node40.msh", file41("1 4 1 4", "2 1 0 4", "0 1 0\n", "2 1 3 1", "1 1 2 3 40"));
  EXPECT_EQ(gmshError(path), path +
                                 ":19: element 1 refers to node 40, which is not defined (expected a node of the "
                                 "$Nodes section at line 4)");
  path = writeFile("v41_3_nodes.msh", file41("1 4 1 4", "2 1 0 4", "0 1 0\n", "2 1 3 1", "1 1 2 3"));
  EXPECT_EQ(gmshError(path), path +
                                 ":19: found '1 1 2 3' (expected an element tag and 4 nodes: gmsh type 3, QUAD4, "
                                 "block at line 18)");
  path = writeFile("v41_extra_block.msh", file41("1 4 1 4", "2 1 0 4", "0 1 0\n", "2 1 3 1", "1 1 2 3 4", "2 1 3 1\n"));
  EXPECT_EQ(gmshError(path), path +
                                 ":20: found '2 1 3 1' after the 1 element block announced at line 17 (expected "
                                 "$EndElements)");
}

TEST(MshCheck, GmshFailureKeepsItsMessageAndSaysWhatWasExpected) {
  // The lines of ASCII $Entities are left to gmsh (their number is checked), which finds them wrong.
  const std::string path = writeFile("ascii_entities_garbage.msh",
                                     "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n1 0 0 0\ngarbage\n$EndEntities\n");
  const std::string message = gmshError(path);
  EXPECT_EQ(message.rfind(path + ": gmsh error: ", 0), 0u) << message;
  EXPECT_TRUE(endsWith(message, " (expected a gmsh .msh file, version 2.2 or 4.1)")) << message;

  // MSH 4.0 is left to gmsh: an element type gmsh knows (27, a 5-node line) but
  // code_aster has not is reported with the supported types.
  const std::string lin5 =
      writeFile("lin5_40.msh",
                "$MeshFormat\n4 0 8\n$EndMeshFormat\n$Nodes\n1 5\n1 1 0 5\n1 0 0 0\n2 1 0 0\n3 0.25 0 0\n4 0.5 0 0\n"
                "5 0.75 0 0\n$EndNodes\n$Elements\n1 1\n1 1 27 1\n1 1 2 3 4 5\n$EndElements\n");
  const std::string m = gmshError(lin5);
  EXPECT_EQ(m.rfind(lin5 + ": gmsh element type 27 (", 0), 0u) << m;
  EXPECT_TRUE(endsWith(m, ") has no code_aster equivalent (expected one of the gmsh types " + kSupported + ")")) << m;
}

TEST(MshCheck, GmshTypeTable) {
  EXPECT_EQ(cellTypeOfGmshElement(16), CellType::QUAD8);
  EXPECT_EQ(cellTypeOfGmshElement(15), CellType::POI1);
  EXPECT_FALSE(cellTypeOfGmshElement(21));  // 10-node triangle
  EXPECT_EQ(gmshElementType(CellType::HEXA27), 12);
  EXPECT_THROW(gmshElementType(CellType::TRIA7), aster::Error);
  EXPECT_EQ(supportedGmshElementTypes(), kSupported);
}

TEST(MedErrors, NotHdf5) {
  for (const auto& [name, text] : {std::pair<std::string, std::string>{"text.med", "this is not a MED file\n"},
                                   {"empty.med", ""},
                                   {"short.med", "\x89HDF"}}) {
    const std::string path = writeFile(name, text);
    EXPECT_EQ(medError(path),
              path +
                  ": not a MED file (no HDF5 signature): expected a MED file written by Salome, code_aster or "
                  "aster-lite");
    EXPECT_EQ(errorOf([&] { readMedNodalField(path, "DEPL", 1); }),
              path +
                  ": not a MED file (no HDF5 signature): expected a MED file written by Salome, code_aster or "
                  "aster-lite");
  }
  EXPECT_EQ(medError(kTmp + "no-such-file.med"), "cannot open the MED file '" + kTmp + "no-such-file.med'");
}

TEST(MedErrors, Hdf5ButNotMed) {
  const std::string path = writeFile("hdf5_garbage.med", "\x89HDF\r\n\x1a\n"s + std::string(600, 'x'));
  EXPECT_EQ(medError(path), path +
                                ": an HDF5 file that the MED library cannot open (not a MED file, or a MED version "
                                "newer than 4.1): expected a MED file written by Salome, code_aster or aster-lite");
}

TEST(MedErrors, NoMeshAndAbsentMesh) {
  std::filesystem::create_directories(kTmp);
  const std::string empty = kTmp + "no_mesh.med";
  std::filesystem::remove(empty);
  med_idt fid = MEDfileOpen(empty.c_str(), MED_ACC_CREAT);
  ASSERT_GE(fid, 0);
  MEDfileClose(fid);
  EXPECT_EQ(medError(empty), empty + ": the MED file holds no mesh (expected at least one unstructured mesh)");

  // Two (empty) meshes MA and MC; MB is asked for.
  const std::string two = kTmp + "two_meshes.med";
  std::filesystem::remove(two);
  fid = MEDfileOpen(two.c_str(), MED_ACC_CREAT);
  ASSERT_GE(fid, 0);
  std::string axes(2 * MED_SNAME_SIZE, ' '), units(2 * MED_SNAME_SIZE, ' ');
  axes[0] = 'X';
  axes[MED_SNAME_SIZE] = 'Y';
  for (const char* name : {"MA", "MC"})
    ASSERT_GE(MEDmeshCr(fid, name, 2, 2, MED_UNSTRUCTURED_MESH, "", "", MED_SORT_DTIT, MED_CARTESIAN, axes.c_str(),
                        units.c_str()),
              0);
  MEDfileClose(fid);
  EXPECT_EQ(medError(two, "MB"),
            two + ": no mesh called 'MB' in the MED file (expected one of the meshes present: MA, MC)");
}
