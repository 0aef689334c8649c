// Binary gmsh files (MSH 4.1 and 2.2): checkMshFile reads every section before
// gmsh does, since gmsh's binary readers trust the counts, tags and sizes of the
// file. The files are built here byte by byte, so the offset of each fault is known.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "core/error.hpp"
#include "mesh/io/gmsh_format.hpp"
#include "mesh/io/msh_check.hpp"

using namespace aster::mesh;

namespace {

const std::string kTmp = std::string(ASTER_BINARY_DIR) + "/msh_binary/";

std::string writeFile(const std::string& name, const std::string& bytes) {
  std::filesystem::create_directories(kTmp);
  const std::string path = kTmp + name;
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
  return path;
}

std::string errorOf(const std::string& path) {
  try {
    checkMshFile(path);
  } catch (const aster::Error& e) {
    return e.what();
  }
  return "no error";
}

class Bytes {
 public:
  template <class T>
  Bytes& put(T value) {
    s_.append(reinterpret_cast<const char*>(&value), sizeof value);
    return *this;
  }
  Bytes& text(const std::string& t) {
    s_ += t;
    return *this;
  }
  std::size_t size() const { return s_.size(); }
  const std::string& str() const { return s_; }

 private:
  std::string s_;
};

// One QUAD4 on the unit square, in surface 1 of physical group 1 ("SURF").
// The fields are what the tests damage.
struct File41 {
  std::int32_t one = 1;
  std::string names = "1\n2 1 \"SURF\"\n";
  std::uint64_t nodeTotal = 4, nodeBlockCount = 4, lastNodeTag = 4;
  std::int32_t nodeDim = 2, parametric = 0;
  double lastX = 0.0;
  std::uint64_t elementTotal = 1, elementTag = 1, lastElementNode = 4;
  std::int32_t elementDim = 2, elementEntity = 1, elementType = 3;  // QUAD4
  std::string extra;  // a section after $Elements
  // Offsets of the fields, set by bytes().
  std::size_t nodesAt = 0, nodeTotalAt = 0, nodeBlockAt = 0, elementsAt = 0, elementBlockAt = 0, elementAt = 0;

  std::string bytes() {
    Bytes b;
    b.text("$MeshFormat\n4.1 1 8\n").put(one).text("\n$EndMeshFormat\n");
    b.text("$PhysicalNames\n" + names + "$EndPhysicalNames\n");
    b.text("$Entities\n").put<std::uint64_t>(0).put<std::uint64_t>(0).put<std::uint64_t>(1).put<std::uint64_t>(0);
    b.put<std::int32_t>(1);
    for (double x : {0.0, 0.0, 0.0, 1.0, 1.0, 0.0}) b.put(x);
    b.put<std::uint64_t>(1).put<std::int32_t>(1).put<std::uint64_t>(0).text("\n$EndEntities\n");
    nodesAt = b.size();
    b.text("$Nodes\n");
    nodeTotalAt = b.size() + 8;
    b.put<std::uint64_t>(1).put(nodeTotal).put<std::uint64_t>(1).put<std::uint64_t>(4);
    nodeBlockAt = b.size();
    b.put(nodeDim).put<std::int32_t>(1).put(parametric).put(nodeBlockCount);
    for (std::uint64_t t : {std::uint64_t{1}, std::uint64_t{2}, std::uint64_t{3}, lastNodeTag}) b.put(t);
    for (double x : {0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 0.0, lastX, 1.0, 0.0}) b.put(x);
    b.text("\n$EndNodes\n");
    elementsAt = b.size();
    b.text("$Elements\n").put<std::uint64_t>(1).put(elementTotal).put<std::uint64_t>(1).put<std::uint64_t>(1);
    elementBlockAt = b.size();
    b.put(elementDim).put(elementEntity).put(elementType).put<std::uint64_t>(1);
    elementAt = b.size();
    b.put(elementTag).put<std::uint64_t>(1).put<std::uint64_t>(2).put<std::uint64_t>(3).put(lastElementNode);
    b.text("\n$EndElements\n" + extra);
    return b.str();
  }
};

std::string at(const std::string& path, std::size_t byte, const std::string& section, std::size_t sectionAt) {
  return path + ": byte " + std::to_string(byte) + " (binary section $" + section + " at byte " +
         std::to_string(sectionAt) + "): ";
}

}  // namespace

TEST(MshBinary, WellFormedFilesOfBothVersionsAreRead) {
  File41 f;
  const Mesh m = readGmshMesh(writeFile("ok41.msh", f.bytes()));
  ASSERT_EQ(m.cellCount(), 1);
  EXPECT_EQ(m.cellType(0), CellType::QUAD4);
  EXPECT_EQ(m.nodeCount(), 4);
  EXPECT_EQ(m.cellGroup("SURF").size(), 1u);

  // MSH 2.2: the counts are text lines; elements come in blocks of one type.
  Bytes b;
  b.text("$MeshFormat\n2.2 1 8\n").put<std::int32_t>(1).text("\n$EndMeshFormat\n");
  b.text("$PhysicalNames\n1\n2 7 \"SURF\"\n$EndPhysicalNames\n$Nodes\n4\n");
  const double xyz[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (int i = 0; i < 4; ++i) {
    b.put<std::int32_t>(i + 1);
    for (double x : xyz[i]) b.put(x);
  }
  b.text("\n$EndNodes\n$Elements\n1\n");
  for (std::int32_t v : {3, 1, 2, 1, 7, 1, 1, 2, 3, 4}) b.put(v);  // QUAD4, 1 element, 2 tags: tag 1, physical 7, entity 1
  b.text("\n$EndElements\n");
  const Mesh m22 = readGmshMesh(writeFile("ok22.msh", b.str()));
  ASSERT_EQ(m22.cellCount(), 1);
  EXPECT_EQ(m22.cellGroup("SURF").size(), 1u);

  // The same file with 5 nodes announced: the records end elsewhere than $EndNodes.
  std::string bad = b.str();
  bad.replace(bad.find("$Nodes\n4\n"), 9, "$Nodes\n5\n");
  const std::string path = writeFile("count22.msh", bad);
  const std::size_t nodesAt = bad.find("$Nodes"), countAt = nodesAt + 7;
  EXPECT_EQ(errorOf(path), at(path, countAt, "Nodes", nodesAt) +
                               "5 nodes of 28 bytes announced, but $EndNodes does not follow them at byte " +
                               std::to_string(countAt + 2 + 5 * 28) +
                               " (expected the number of nodes of the section: a wrong count or a damaged file)");
}

TEST(MshBinary, CountsLargerThanTheirBlocks) {
  File41 f;
  f.nodeTotal = 3;  // the block holds 4: gmsh wrote past its array
  std::string path = writeFile("node_total.msh", f.bytes());
  EXPECT_EQ(errorOf(path), at(path, f.nodeBlockAt, "Nodes", f.nodesAt) +
                               "node block 1 holds 4 nodes, more than the 3 announced at byte " +
                               std::to_string(f.nodeTotalAt) + " (the blocks before it hold 0)");

  File41 g;
  g.nodeTotal = 5;  // one node missing
  path = writeFile("node_total5.msh", g.bytes());
  EXPECT_EQ(errorOf(path), at(path, g.nodeTotalAt, "Nodes", g.nodesAt) +
                               "the node blocks hold 4 nodes (expected 5, as announced here)");

  File41 h;
  h.nodeBlockCount = std::numeric_limits<std::uint64_t>::max() / 2;
  path = writeFile("node_block.msh", h.bytes());
  const std::string message = errorOf(path);
  EXPECT_EQ(message.rfind(at(path, h.nodeBlockAt + 12, "Nodes", h.nodesAt) + "the number of nodes of node block 1 is " +
                              std::to_string(h.nodeBlockCount) + ", more than the ",
                          0),
            0u)
      << message;

  // Cut inside the nodes' coordinates: the count of the block is more than what is left.
  File41 t;
  const std::string whole = t.bytes();
  path = writeFile("truncated.msh", whole.substr(0, t.elementsAt - 30));
  EXPECT_EQ(errorOf(path), at(path, t.nodeBlockAt + 12, "Nodes", t.nodesAt) +
                               "the number of nodes of node block 1 is 4, more than the 109 bytes left in the file can "
                               "hold (32 bytes or more each): a damaged count or a truncated file");
  // Cut inside a header: the total is more than what is left.
  path = writeFile("truncated_header.msh", whole.substr(0, t.nodeBlockAt + 6));
  EXPECT_EQ(errorOf(path), at(path, t.nodeTotalAt, "Nodes", t.nodesAt) +
                               "the number of nodes is 4, more than the 22 bytes left in the file can hold (32 bytes or "
                               "more each): a damaged count or a truncated file");
}

TEST(MshBinary, TagsTypesAndEntities) {
  File41 f;
  f.lastNodeTag = 2;
  std::string path = writeFile("duplicate_node.msh", f.bytes());
  EXPECT_EQ(errorOf(path), at(path, f.nodeBlockAt + 20 + 24, "Nodes", f.nodesAt) +
                               "node 2 is defined twice (expected distinct node tags; the first is at byte " +
                               std::to_string(f.nodeBlockAt + 20 + 8) + ")");

  File41 x;
  x.lastX = std::numeric_limits<double>::quiet_NaN();
  path = writeFile("nan.msh", x.bytes());
  EXPECT_EQ(errorOf(path), at(path, x.nodeBlockAt + 20 + 24, "Nodes", x.nodesAt) +
                               "node 4 has a coordinate that is not a finite number (expected finite coordinates)");

  File41 n;
  n.lastElementNode = (std::uint64_t{1} << 32) + 4;  // gmsh read it as node 4
  path = writeFile("node_64bit.msh", n.bytes());
  EXPECT_EQ(errorOf(path), at(path, n.elementAt + 32, "Elements", n.elementsAt) +
                               "element 1 refers to node 4294967300, which is not defined (expected a node of a "
                               "$Nodes section before $Elements, at byte " +
                               std::to_string(n.nodesAt) + ")");

  File41 d;
  d.elementDim = 1;  // a QUAD4 in a curve: gmsh drops it
  d.elementEntity = 1;
  path = writeFile("element_dim.msh", d.bytes());
  EXPECT_EQ(errorOf(path), at(path, d.elementBlockAt, "Elements", d.elementsAt) +
                               "element block 1 is in entity 1 of dimension 1, which is not defined (expected an "
                               "entity of $Entities or of a node block)");
  File41 d2;
  d2.elementType = 1;  // SEG2 in the surface
  path = writeFile("element_type_dim.msh", d2.bytes());
  const std::string m = errorOf(path);
  EXPECT_EQ(m, at(path, d2.elementBlockAt, "Elements", d2.elementsAt) +
                   "element block 1 has elements of gmsh type 1, SEG2, cells of dimension 1 (expected cells of "
                   "dimension 2, the dimension of their entity)")
      << m;

  File41 u;
  u.elementType = 21;  // a 10-node triangle
  path = writeFile("element_type.msh", u.bytes());
  const std::string um = errorOf(path);
  EXPECT_EQ(um.rfind(at(path, u.elementBlockAt, "Elements", u.elementsAt) +
                         "element block 1 has elements of gmsh type 21, which aster-lite does not read",
                     0),
            0u)
      << um;

  File41 z;
  z.elementTag = 0;
  path = writeFile("element_tag0.msh", z.bytes());
  EXPECT_EQ(errorOf(path), at(path, z.elementAt, "Elements", z.elementsAt) + "element tag 0 (expected element tags >= 1)");
}

TEST(MshBinary, FramingAndSections) {
  File41 f;
  f.one = 0x01000000;  // another byte order
  std::string path = writeFile("swapped.msh", f.bytes());
  EXPECT_EQ(errorOf(path), at(path, 20, "MeshFormat", 0) +
                               "found the binary integer 16777216 after the version line (expected 1: a file written "
                               "on a machine of another byte order, or a damaged file)");

  // The file ends with the version line.
  path = writeFile("version_only.msh", "$MeshFormat\n4.1 1 8");
  EXPECT_EQ(errorOf(path), at(path, 19, "MeshFormat", 0) +
                               "the file ends inside the integer 1 that follows the version line (truncated file?)");

  File41 p;
  p.extra = "$Periodic\n1\n$EndPeriodic\n";
  path = writeFile("periodic.msh", p.bytes());
  const std::size_t periodicAt = p.bytes().size() - p.extra.size();
  EXPECT_EQ(errorOf(path), at(path, periodicAt, "Periodic", periodicAt) +
                               "aster-lite does not read section $Periodic in a binary file (expected the sections "
                               "$PhysicalNames, $Entities, $Nodes and $Elements only; save the mesh as ASCII to keep "
                               "the others)");

  // A section gmsh does not know is skipped, as gmsh does; its end must be there.
  File41 c;
  c.extra = "$Comments\nwritten by hand\n$EndComments\n";
  EXPECT_NO_THROW(checkMshFile(writeFile("comments.msh", c.bytes())));
  File41 o;
  o.extra = "$Comments\nwritten by hand\n";
  path = writeFile("open_comments.msh", o.bytes());
  const std::size_t endAt = o.bytes().size();
  EXPECT_EQ(errorOf(path), at(path, endAt, "Comments", endAt - 26) +
                               "the file ends inside section $Comments (expected $EndComments; truncated file?)");

  File41 n;
  n.names = "1\n7 1 \"SURF\"\n";  // gmsh indexes a table of 4 by the dimension
  path = writeFile("name_dim.msh", n.bytes());
  const std::size_t namesAt = n.bytes().find("$PhysicalNames");
  EXPECT_EQ(errorOf(path), at(path, namesAt + 17, "PhysicalNames", namesAt) +
                               "physical name '\"SURF\"' has dimension 7 (expected 0, 1, 2 or 3)");

  // MSH 4.0 is binary only in version 4.1 for gmsh.
  std::string v40 = f.bytes();
  v40.replace(v40.find("4.1 1 8"), 7, "4 1 8");
  path = writeFile("v40.msh", v40);
  EXPECT_EQ(errorOf(path), at(path, 18, "MeshFormat", 0) +
                               "a binary file of MSH version 4.0 (expected version 4.1 or 2.2 for a binary file; gmsh "
                               "reads 4.0 in ASCII only)");
}

// The file is framed as gmsh frames it: in chunks of at most 1023 bytes (255 for
// MSH 2.2), each a line or a piece of a longer line; a chunk that starts with '$'
// opens a section, wherever it lies.
TEST(MshBinary, ChunksAsGmshReadsThem) {
  const std::string header = "$MeshFormat\n4.1 1 8\n" + std::string("\x01\0\0\0", 4) + "\n$EndMeshFormat\n";
  // "$Entities" and binary counts on one 1023-byte chunk: gmsh compares the
  // beginning of the chunk with "$Entities" and reads counts after it.
  const std::size_t entitiesAt = header.size();
  std::string path = writeFile("long_chunk.msh", header + "$Entities" + std::string(1014, '\x01') + "\n");
  std::string cut;
  for (int k = 0; k < 51; ++k) cut += "\\x01";
  EXPECT_EQ(errorOf(path), at(path, entitiesAt, "Entities", entitiesAt) + "found '$Entities" + cut +
                               "...' (expected a section marker '$Name' alone on its line)");

  // Text of 1030 bytes between sections: its second chunk starts with '$'.
  File41 t;
  t.extra = std::string(1023, 'x') + "$Periodic\n1\n$EndPeriodic\n";
  path = writeFile("long_text.msh", t.bytes());
  const std::size_t periodicAt = t.bytes().size() - t.extra.size() + 1023;
  EXPECT_EQ(errorOf(path), at(path, periodicAt, "Periodic", periodicAt) +
                               "aster-lite does not read section $Periodic in a binary file (expected the sections "
                               "$PhysicalNames, $Entities, $Nodes and $Elements only; save the mesh as ASCII to keep "
                               "the others)");
  // The same text with a newline is skipped, and a last line without newline ends the file.
  t.extra = std::string(1023, 'x') + "\n$Comments\n" + std::string(2000, 'y') + "\n$EndComments\nlast";
  EXPECT_EQ(errorOf(writeFile("long_text_ok.msh", t.bytes())), "no error");

  // gmsh ends a section it skips at a chunk "<any byte>End<name>" and the
  // marker's trailer, not only at "$End<name>".
  File41 c;
  c.extra = "$Comments\nxEndComments\n$EndComments\n";
  path = writeFile("comments_x_end.msh", c.bytes());
  const std::size_t xAt = c.bytes().size() - c.extra.size() + 10;
  EXPECT_EQ(errorOf(path), at(path, xAt, "Comments", xAt - 10) +
                               "found 'xEndComments' inside section $Comments, which ends the section for gmsh "
                               "(expected $EndComments)");

  // A section name is printable: gmsh would cut it at a zero byte.
  File41 z;
  z.extra = std::string("$Foo\x01\n$EndFoo\x01\n");
  path = writeFile("name_control.msh", z.bytes());
  const std::size_t fooAt = z.bytes().size() - z.extra.size();
  EXPECT_EQ(errorOf(path), at(path, fooAt, "Foo", fooAt) +
                               "found '$Foo\\x01' (expected a section marker '$Name' alone on its line)");
}
