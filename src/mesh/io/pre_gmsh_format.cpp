#include "mesh/io/pre_gmsh_format.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <fstream>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/error.hpp"
#include "mesh/io/aster_format.hpp"
#include "mesh/node_ordering.hpp"

namespace aster::mesh {

namespace {

constexpr const char* kExpectedFile =
    "(expected a gmsh MSH 1 file, $NOD ... $ENDELM, or MSH 2 ASCII, $MeshFormat 2.x 0 8, as code_aster's PRE_GMSH "
    "reads them)";

// What PRE_GMSH makes of gmsh element type t (1..19): the code_aster type,
// the number of nodes gmsh writes, the number code_aster keeps (the first ones).
struct TypeMap {
  CellType type;
  int gmshNodes;
};
constexpr int kGmshTypeCount = 19;
const TypeMap kTypes[kGmshTypeCount] = {
    {CellType::SEG2, 2},    {CellType::TRIA3, 3},   {CellType::QUAD4, 4},    {CellType::TETRA4, 4},
    {CellType::HEXA8, 8},   {CellType::PENTA6, 6},  {CellType::PYRAM5, 5},   {CellType::SEG3, 3},
    {CellType::TRIA6, 6},   {CellType::QUAD8, 9},   {CellType::TETRA10, 10}, {CellType::HEXA27, 27},
    {CellType::PENTA18, 18}, {CellType::PYRAM13, 14}, {CellType::POI1, 1},   {CellType::QUAD8, 8},
    {CellType::HEXA20, 20}, {CellType::PENTA15, 15}, {CellType::PYRAM13, 13}};

struct Word {
  std::string_view text;
  int line = 0;
};

class Words {
 public:
  Words(const std::string& text, std::string source) : source_(std::move(source)) {
    int line = 1;
    std::size_t i = 0;
    while (i < text.size()) {
      const char c = text[i];
      if (c == '\n') {
        ++line;
        ++i;
      } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
        ++i;
      } else {
        const std::size_t start = i;
        while (i < text.size() && text[i] != '\n' && text[i] != ' ' && text[i] != '\t' && text[i] != '\r' &&
               text[i] != '\f' && text[i] != '\v')
          ++i;
        words_.push_back({std::string_view(text.data() + start, i - start), line});
      }
    }
    lastLine_ = line;
  }

  bool atEnd() const { return next_ >= words_.size(); }
  const Word& peek() const { return words_[next_]; }
  int line() const { return atEnd() ? lastLine_ : words_[next_].line; }

  [[noreturn]] void fail(int line, const std::string& what) const {
    throw Error(source_ + ":" + std::to_string(line) + ": " + what);
  }

  const Word& take(const std::string& what) {
    if (atEnd()) fail(lastLine_, "the file ends where " + what + " was expected (truncated file?)");
    return words_[next_++];
  }
  void expect(const char* marker) {
    const Word& w = take(marker);
    if (w.text != marker)
      fail(w.line, "expected " + std::string(marker) + ", found '" + std::string(w.text) + "' " + kExpectedFile);
  }
  long integer(const std::string& what) {
    const Word& w = take(what);
    long v = 0;
    const auto r = std::from_chars(w.text.data(), w.text.data() + w.text.size(), v);
    if (r.ec != std::errc() || r.ptr != w.text.data() + w.text.size())
      fail(w.line, "expected " + what + " (an integer), found '" + std::string(w.text) + "'");
    return v;
  }
  double real(const std::string& what) {
    const Word& w = take(what);
    char buffer[64];
    if (!w.text.empty() && w.text.size() < sizeof buffer) {
      std::copy(w.text.begin(), w.text.end(), buffer);
      buffer[w.text.size()] = '\0';
      errno = 0;
      char* end = nullptr;
      const double v = std::strtod(buffer, &end);
      if (end == buffer + w.text.size() && errno != ERANGE) return v;
    }
    fail(w.line, "expected " + what + " (a number), found '" + std::string(w.text) + "'");
  }
  // Skips words up to and including `marker`; false when the file ends first.
  bool skipPast(std::string_view marker) {
    while (!atEnd())
      if (words_[next_++].text == marker) return true;
    return false;
  }

 private:
  std::string source_;
  std::vector<Word> words_;
  std::size_t next_ = 0;
  int lastLine_ = 1;
};

struct GmshNode {
  long number;
  double x, y, z;
};

struct GmshElement {
  long number;
  int gmshType;  // 1..19
  long physical;
  int line;
  std::size_t firstNode;  // into nodeNumbers
};

class PreGmshReader {
 public:
  PreGmshReader(const std::string& text, const std::string& source) : in_(text, source) {}

  Mesh read() {
    if (in_.atEnd()) in_.fail(1, "the file is empty " + std::string(kExpectedFile));
    const Word& first = in_.take("$NOD or $MeshFormat");
    if (first.text == "$NOD") {
      version_ = 1;
    } else if (first.text == "$MeshFormat") {
      version_ = 2;
      const Word& v = in_.take("the version of the file");
      if (v.text.substr(0, 2) != "2." && v.text != "2")
        in_.fail(v.line, "MSH version " + std::string(v.text) +
                             ": PRE_GMSH reads MSH 1 and 2 (LIRE_MAILLAGE{FORMAT='GMSH'} reads version 4) " +
                             kExpectedFile);
      const Word& fileType = in_.peek();
      if (in_.integer("the file type (0 for ASCII)") != 0)
        in_.fail(fileType.line, "a binary MSH file: PRE_GMSH reads ASCII files (LIRE_MAILLAGE{FORMAT='GMSH'} "
                                "reads binary ones) " + std::string(kExpectedFile));
      if (!in_.skipPast("$Nodes")) in_.fail(in_.line(), "the file has no $Nodes section " + std::string(kExpectedFile));
    } else {
      in_.fail(first.line, "expected $NOD or $MeshFormat, found '" + std::string(first.text) + "' " + kExpectedFile);
    }
    readNodes();
    in_.expect(version_ == 1 ? "$ENDNOD" : "$EndNodes");
    in_.expect(version_ == 1 ? "$ELM" : "$Elements");
    readElements();
    in_.expect(version_ == 1 ? "$ENDELM" : "$EndElements");
    return build();
  }

 private:
  void readNodes() {
    const long count = in_.integer("the number of nodes");
    if (count < 0) in_.fail(in_.line(), "negative number of nodes");
    nodes_.reserve(static_cast<std::size_t>(std::min(count, 1L << 20)));  // the count may lie
    for (long k = 0; k < count; ++k) {
      const int line = in_.line();
      const long number = in_.integer("a node number");
      GmshNode n{number, 0, 0, 0};
      n.x = in_.real("the x of node " + std::to_string(number));
      n.y = in_.real("the y of node " + std::to_string(number));
      n.z = in_.real("the z of node " + std::to_string(number));
      if (!nodeIndex_.emplace(number, static_cast<int>(nodes_.size())).second)
        in_.fail(line, "node " + std::to_string(number) + " is defined twice");
      nodes_.push_back(n);
    }
  }

  void readElements() {
    const long count = in_.integer("the number of elements");
    if (count < 0) in_.fail(in_.line(), "negative number of elements");
    elements_.reserve(static_cast<std::size_t>(std::min(count, 1L << 20)));
    std::unordered_map<long, int> seen;
    for (long k = 0; k < count; ++k) {
      GmshElement e{};
      e.line = in_.line();
      e.number = in_.integer("an element number");
      const std::string what = "element " + std::to_string(e.number);
      const Word& typeWord = in_.peek();
      const long type = in_.integer("the type of " + what);
      if (type < 1 || type > kGmshTypeCount)
        in_.fail(typeWord.line, what + " has gmsh type " + std::to_string(type) +
                                    ", which PRE_GMSH does not convert (expected 1 to 19: points, lines, "
                                    "triangles, quadrangles, tetrahedra, hexahedra, prisms, pyramids of order 1 or 2)");
      e.gmshType = static_cast<int>(type);
      const int expectedNodes = kTypes[type - 1].gmshNodes;
      if (version_ == 1) {
        e.physical = in_.integer("the physical tag of " + what);
        in_.integer("the elementary tag of " + what);
        const long n = in_.integer("the number of nodes of " + what);
        if (n != expectedNodes)
          in_.fail(e.line, what + " of gmsh type " + std::to_string(type) + " has " + std::to_string(n) +
                               " nodes, expected " + std::to_string(expectedNodes));
      } else {
        const long tags = in_.integer("the number of tags of " + what);
        if (tags < 0 || tags > 100) in_.fail(e.line, what + ": bad number of tags " + std::to_string(tags));
        e.physical = 0;
        for (long t = 0; t < tags; ++t) {
          const long tag = in_.integer("a tag of " + what);
          if (t == 0) e.physical = tag;
        }
      }
      if (e.physical < 0 || e.physical >= 1000000)
        in_.fail(e.line, what + " has the physical tag " + std::to_string(e.physical) +
                             " (PRE_GMSH names the group GM<tag>: expected a tag from 0 to 999999)");
      e.firstNode = nodeNumbers_.size();
      for (int j = 0; j < expectedNodes; ++j) {
        const Word& w = in_.peek();
        const long node = in_.integer("node " + std::to_string(j + 1) + " of " + what);
        if (!nodeIndex_.count(node))
          in_.fail(w.line, "node " + std::to_string(node) + " of " + what + " is not defined in the nodes section");
        nodeNumbers_.push_back(node);
      }
      if (!seen.emplace(e.number, e.line).second)
        in_.fail(e.line, "element " + std::to_string(e.number) + " is defined twice (first at line " +
                             std::to_string(seen[e.number]) + ")");
      elements_.push_back(e);
    }
  }

  Mesh build() {
    // The code_aster nodes of each element, in code_aster's order.
    std::vector<std::vector<long>> cellNodes(elements_.size());
    std::vector<char> used(nodes_.size(), 0);
    for (std::size_t k = 0; k < elements_.size(); ++k) {
      const GmshElement& e = elements_[k];
      const CellType type = kTypes[e.gmshType - 1].type;
      // The first nodes of gmsh's QUAD9 and 14-node pyramid are its QUAD8 and PYRAM13:
      // the permutation of those drops the centre.
      for (int j : asterFromForeign(NodeConvention::Gmsh, type)) {
        const long number = nodeNumbers_[e.firstNode + static_cast<std::size_t>(j)];
        cellNodes[k].push_back(number);
        used[static_cast<std::size_t>(nodeIndex_.at(number))] = 1;
      }
    }
    Mesh mesh;
    mesh.setSpaceDimension(3);
    std::unordered_map<long, int> meshNode;
    for (std::size_t i = 0; i < nodes_.size(); ++i)
      if (used[i]) meshNode[nodes_[i].number] = mesh.addNode({nodes_[i].x, nodes_[i].y, nodes_[i].z},
                                                             "N" + std::to_string(nodes_[i].number));
    // Cells by gmsh type, file order within a type.
    std::vector<std::size_t> order(elements_.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return elements_[a].gmshType < elements_[b].gmshType; });
    std::vector<int> meshCell(elements_.size());
    std::vector<int> nodes;
    for (std::size_t k : order) {
      nodes.clear();
      for (long number : cellNodes[k]) nodes.push_back(meshNode.at(number));
      meshCell[k] = mesh.addCell(kTypes[elements_[k].gmshType - 1].type, nodes, "M" + std::to_string(elements_[k].number));
    }
    // Groups GM<physical>, in order of first appearance.
    std::vector<long> physicals;
    std::unordered_map<long, std::vector<int>> members;
    for (std::size_t k = 0; k < elements_.size(); ++k) {
      const long p = elements_[k].physical;
      if (p == 0) continue;
      auto& m = members[p];
      if (m.empty()) physicals.push_back(p);
      m.push_back(meshCell[k]);
    }
    for (long p : physicals) {
      const std::string name = "GM" + std::to_string(p);
      const std::vector<int>& cells = members[p];
      mesh.addCellGroup(name, cells);
      if (cells.size() == 1 && mesh.cellType(cells[0]) == CellType::POI1)
        mesh.addNodeGroup(name, {mesh.cellNodes(cells[0])[0]});
    }
    return mesh;
  }

  Words in_;
  int version_ = 1;
  std::vector<GmshNode> nodes_;
  std::unordered_map<long, int> nodeIndex_;  // gmsh number -> index in nodes_
  std::vector<GmshElement> elements_;
  std::vector<long> nodeNumbers_;
};

}  // namespace

bool isPreGmshOnlyFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string first, version;
  if (!(in >> first)) return false;
  if (first == "$NOD") return true;
  return first == "$MeshFormat" && static_cast<bool>(in >> version) &&
         (version == "2" || version == "2.0" || version == "2.1");
}

Mesh parseGmshAsPreGmsh(const std::string& text, const std::string& sourceName) {
  return PreGmshReader(text, sourceName).read();
}

Mesh readGmshAsPreGmsh(const std::string& path) { return parseGmshAsPreGmsh(meshFileText(path), path); }

}  // namespace aster::mesh
