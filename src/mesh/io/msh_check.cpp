#include "mesh/io/msh_check.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <unordered_set>
#include <vector>

#include "core/error.hpp"
#include "mesh/io/words.hpp"

namespace aster::mesh {

namespace {

struct GmshPair {
  CellType type;
  int gmsh;
};

// gmsh's element type numbers (GmshDefines.h: MSH_PNT = 15, MSH_LIN_2 = 1, ...).
constexpr GmshPair kGmshTypes[] = {
    {CellType::POI1, 15},    {CellType::SEG2, 1},     {CellType::SEG3, 8},     {CellType::SEG4, 26},
    {CellType::TRIA3, 2},    {CellType::TRIA6, 9},    {CellType::QUAD4, 3},    {CellType::QUAD8, 16},
    {CellType::QUAD9, 10},   {CellType::TETRA4, 4},   {CellType::TETRA10, 11}, {CellType::PENTA6, 6},
    {CellType::PENTA15, 18}, {CellType::PENTA18, 13}, {CellType::PYRAM5, 7},   {CellType::PYRAM13, 19},
    {CellType::HEXA8, 5},    {CellType::HEXA20, 17},  {CellType::HEXA27, 12}};

// Text as it can go in a message: control and non-ASCII bytes escaped.
std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const unsigned char b = static_cast<unsigned char>(c);
    if (b < 32 || b >= 127) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", b);
      out += hex;
    } else {
      out += c;
    }
  }
  return out;
}

// A line quoted in a message: trimmed, escaped, cut when long.
std::string shown(const std::string& line) {
  std::size_t begin = 0, end = line.size();
  while (begin < end && isBlank(line[begin])) ++begin;
  while (end > begin && isBlank(line[end - 1])) --end;
  constexpr std::size_t kMax = 60;
  const bool cut = end - begin > kMax;
  return "'" + escaped(line.substr(begin, cut ? kMax : end - begin)) + (cut ? "...'" : "'");
}

bool parseInteger(const std::string& word, long long& value) {
  if (word.empty()) return false;
  errno = 0;
  char* stop = nullptr;
  value = std::strtoll(word.c_str(), &stop, 10);
  return errno == 0 && stop == word.c_str() + word.size();
}

bool parseReal(const std::string& word, double& value) {
  if (word.empty()) return false;
  errno = 0;
  char* stop = nullptr;
  value = std::strtod(word.c_str(), &stop);
  return errno == 0 && stop == word.c_str() + word.size() && std::isfinite(value);
}

// All words integers (at least `minimum` of them).
bool parseIntegers(const std::vector<std::string>& words, std::vector<long long>& values, std::size_t minimum) {
  values.assign(words.size(), 0);
  if (words.size() < minimum) return false;
  for (std::size_t k = 0; k < words.size(); ++k)
    if (!parseInteger(words[k], values[k])) return false;
  return true;
}

std::string gmshTypeText(int gmshType, CellType type) {
  return "gmsh type " + std::to_string(gmshType) + ", " + cellTypeName(type);
}

std::string unsupportedType(long long gmshType) {
  return "gmsh type " + std::to_string(gmshType) + ", which aster-lite does not read (expected one of the gmsh types " +
         supportedGmshElementTypes() + ")";
}

std::string plural(std::size_t n, const std::string& word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

class MshChecker {
 public:
  explicit MshChecker(std::string path) : path_(std::move(path)) {}

  void run() {
    std::ifstream in(path_, std::ios::binary);
    if (!in) throw Error("cannot open the gmsh file '" + path_ + "'");
    std::string line;
    // Header: $MeshFormat, then "<version> <file-type> <data-size>".
    std::size_t first = 0;
    while (std::getline(in, line)) {
      ++line_;
      if (!splitWords(line).empty()) {
        first = line_;
        break;
      }
    }
    if (first == 0)
      throw Error(path_ + ": the file is empty (expected " + std::string(kMshExpected) +
                  ", starting with $MeshFormat)");
    if (splitWords(line)[0] != "$MeshFormat")
      fail(line_, "found " + shown(line) + " (expected $MeshFormat, the first line of " + kMshExpected + ")");
    // gmsh reads a file that does not start with "$MeshFormat" as a .geo script.
    if (first > 1)
      fail(1, "found an empty line (expected $MeshFormat on the first line of " + std::string(kMshExpected) +
                  ", not on line " + std::to_string(first) + ")");
    if (line[0] != '$')
      fail(1, "found blanks before $MeshFormat (expected $MeshFormat at the start of the first line of " +
                  std::string(kMshExpected) + ")");
    const char* headerForm = "'<version> <file-type> <data-size>', e.g. '4.1 0 8'";
    if (!std::getline(in, line))
      fail(line_, std::string("the file ends after $MeshFormat (expected ") + headerForm + ")");
    ++line_;
    const auto words = splitWords(line);
    double version = 0;
    long long fileType = 0, dataSize = 0;
    if (words.size() != 3 || !parseReal(words[0], version) || !parseInteger(words[1], fileType) ||
        !parseInteger(words[2], dataSize))
      fail(line_, "found " + shown(line) + " after $MeshFormat (expected " + headerForm + ")");
    if (std::fabs(version - 2.2) < 1e-9)
      version_ = 22;
    else if (std::fabs(version - 4.0) < 1e-9)
      version_ = 40;
    else if (std::fabs(version - 4.1) < 1e-9)
      version_ = 41;
    else
      fail(line_, "MSH version " + words[0] + " is not supported (expected 2.2, 4.0 or 4.1)");
    if (fileType != 0 && fileType != 1)
      fail(line_, "file type " + words[1] + " (expected 0 for ASCII or 1 for binary)");
    if (dataSize != 8) fail(line_, "data size " + words[2] + " (expected 8, the size of a double)");
    if (fileType == 1) return;  // binary: gmsh reads the rest

    open("MeshFormat", first);
    while (std::getline(in, line)) {
      ++line_;
      const auto w = splitWords(line);
      if (w.empty()) continue;
      if (w[0][0] == '$' && !(section_ == "Comments" && w[0] != "$EndComments")) {
        marker(w[0]);
      } else if (!section_.empty()) {
        content(line, w);
      }
      // Text between sections: gmsh skips it, so does this check.
    }
    if (!section_.empty())
      fail(sectionLine_, "section $" + section_ + " is not closed: the file ends at line " + std::to_string(line_) +
                             " (expected $End" + section_ + "; truncated file?)");
    if (!deferred_.empty()) throw Error(deferred_);
  }

 private:
  enum class Kind { Other, Nodes22, Elements22, Nodes41, Elements41 };

  [[noreturn]] void fail(std::size_t line, const std::string& what) const {
    throw Error(path_ + ":" + std::to_string(line) + ": " + what);
  }
  // An error on a line inside a section: reported when the structure is sound.
  void defer(const std::string& what) {
    if (deferred_.empty()) deferred_ = path_ + ":" + std::to_string(line_) + ": " + what;
  }

  void open(const std::string& name, std::size_t line) {
    section_ = name;
    sectionLine_ = line;
    kind_ = Kind::Other;
    if (name == "Nodes" && version_ == 22) kind_ = Kind::Nodes22;
    if (name == "Elements" && version_ == 22) kind_ = Kind::Elements22;
    if (name == "Nodes" && version_ == 41) kind_ = Kind::Nodes41;
    if (name == "Elements" && version_ == 41) kind_ = Kind::Elements41;
    countLine_ = 0;
    count_ = seen_ = 0;
    blocks_ = blocksSeen_ = blockLine_ = blockItems_ = blockLeft_ = itemsSum_ = 0;
    if (kind_ == Kind::Nodes22 || kind_ == Kind::Nodes41) {
      nodeTags_.clear();
      nodesLine_ = 0;
    }
  }

  void marker(const std::string& raw) {
    const std::string word = escaped(raw);
    if (word.rfind("$End", 0) == 0) {
      const std::string name = word.substr(4);
      if (section_.empty()) fail(line_, "found " + word + " outside any section (expected $" + name + " before it)");
      if (name != section_)
        fail(line_, "found " + word + " inside section $" + section_ + " opened at line " +
                        std::to_string(sectionLine_) + " (expected $End" + section_ + ")");
      close();
      section_.clear();
      return;
    }
    if (!section_.empty())
      fail(line_, "found " + word + " inside section $" + section_ + " opened at line " + std::to_string(sectionLine_) +
                      " (expected $End" + section_ + " first; truncated section?)");
    open(word.substr(1), line_);
  }

  // ---- Lines inside a section ----

  void content(const std::string& line, const std::vector<std::string>& w) {
    if (!deferred_.empty()) return;
    switch (kind_) {
      case Kind::Other:
        return;
      case Kind::Nodes22:
      case Kind::Elements22:
        return content22(line, w);
      case Kind::Nodes41:
      case Kind::Elements41:
        return content41(line, w);
    }
  }

  bool nodes() const { return kind_ == Kind::Nodes22 || kind_ == Kind::Nodes41; }
  std::string what() const { return nodes() ? "node" : "element"; }

  // "<count>" then count lines.
  void content22(const std::string& line, const std::vector<std::string>& w) {
    long long n = 0;
    if (countLine_ == 0) {
      if (w.size() != 1 || !parseInteger(w[0], n) || n < 0)
        return defer("found " + shown(line) + " after $" + section_ + " (expected the number of " + what() + "s)");
      countLine_ = line_;
      count_ = static_cast<std::size_t>(n);
      return;
    }
    if (++seen_ > count_)
      return defer("found " + shown(line) + ", one " + what() + " line more than the " + std::to_string(count_) +
                   " announced at line " + std::to_string(countLine_) + " (expected $End" + section_ + ")");
    if (kind_ == Kind::Nodes22) {
      double x = 0;
      if (w.size() != 4 || !parseInteger(w[0], n) || n < 1 || !parseReal(w[1], x) || !parseReal(w[2], x) ||
          !parseReal(w[3], x))
        return defer("found " + shown(line) + " (expected a node line '<tag> <x> <y> <z>')");
      nodeTags_.insert(n);
      return;
    }
    std::vector<long long> v;
    if (!parseIntegers(w, v, 3) || v[2] < 0)
      return defer("found " + shown(line) +
                   " (expected an element line '<tag> <type> <number of tags> <tags> <nodes>')");
    const auto type = cellTypeOfGmshElement(static_cast<int>(v[1]));
    if (v[1] != static_cast<int>(v[1]) || !type) return defer("element " + w[0] + " has " + unsupportedType(v[1]));
    const long long given = static_cast<long long>(v.size()) - 3 - v[2];
    if (given != nodeCount(*type))
      return defer("element " + w[0] + " (" + gmshTypeText(static_cast<int>(v[1]), *type) + ") has " +
                   plural(static_cast<std::size_t>(std::max(given, 0LL)), "node") + " after its " +
                   plural(static_cast<std::size_t>(v[2]), "tag") + " (expected " + std::to_string(nodeCount(*type)) +
                   ")");
    checkNodes(w[0], v, static_cast<std::size_t>(3 + v[2]));
  }

  // MSH 4.1: "<blocks> <count> <min tag> <max tag>", then blocks of
  // "<dim> <entity> <parametric|type> <n>" followed by n lines (2 n for nodes).
  void content41(const std::string& line, const std::vector<std::string>& w) {
    std::vector<long long> v;
    if (countLine_ == 0) {
      if (!parseIntegers(w, v, 4) || w.size() != 4 || v[0] < 0 || v[1] < 0)
        return defer("found " + shown(line) + " after $" + section_ + " (expected '<blocks> <" + what() +
                     "s> <min tag> <max tag>')");
      countLine_ = line_;
      blocks_ = static_cast<std::size_t>(v[0]);
      count_ = static_cast<std::size_t>(v[1]);
      return;
    }
    if (blockLeft_ == 0) {  // a block header
      if (blocksSeen_ == blocks_)
        return defer("found " + shown(line) + " after the " + plural(blocks_, what() + " block") +
                     " announced at line " + std::to_string(countLine_) + " (expected $End" + section_ + ")");
      const std::string form = nodes() ? "'<entity dim> <entity tag> <parametric> <nodes in block>'"
                                       : "'<entity dim> <entity tag> <element type> <elements in block>'";
      if (!parseIntegers(w, v, 4) || w.size() != 4 || v[0] < 0 || v[0] > 3 || v[3] < 0)
        return defer("found " + shown(line) + " (expected a " + what() + " block header " + form + ")");
      ++blocksSeen_;
      blockLine_ = line_;
      blockItems_ = static_cast<std::size_t>(v[3]);
      itemsSum_ += blockItems_;
      if (nodes()) {
        if (v[2] != 0 && v[2] != 1)
          return defer("found " + shown(line) + " (expected a node block header " + form + ", parametric 0 or 1)");
        coordinates_ = 3 + (v[2] == 1 ? static_cast<int>(v[0]) : 0);
        blockLeft_ = 2 * blockItems_;
      } else {
        const auto type = cellTypeOfGmshElement(static_cast<int>(v[2]));
        if (v[2] != static_cast<int>(v[2]) || !type)
          return defer("the elements of entity " + w[1] + " (dimension " + w[0] + ") have " + unsupportedType(v[2]));
        blockType_ = *type;
        blockGmshType_ = static_cast<int>(v[2]);
        blockLeft_ = blockItems_;
      }
      return;
    }
    --blockLeft_;
    if (nodes()) {
      long long tag = 0;
      if (blockLeft_ >= blockItems_) {  // the tags come first, one per line
        if (w.size() != 1 || !parseInteger(w[0], tag) || tag < 1)
          return defer("found " + shown(line) + " (expected a node tag of the block at line " +
                       std::to_string(blockLine_) + ")");
        nodeTags_.insert(tag);
        return;
      }
      double x = 0;
      bool ok = static_cast<int>(w.size()) == coordinates_;
      for (std::size_t k = 0; ok && k < w.size(); ++k) ok = parseReal(w[k], x);
      if (!ok)
        return defer("found " + shown(line) + " (expected " + std::to_string(coordinates_) +
                     " numbers: the coordinates of a node of the block at line " + std::to_string(blockLine_) + ")");
      return;
    }
    const int nn = nodeCount(blockType_);
    if (!parseIntegers(w, v, 1) || static_cast<int>(v.size()) != 1 + nn)
      return defer("found " + shown(line) + " (expected an element tag and " + std::to_string(nn) + " nodes: " +
                   gmshTypeText(blockGmshType_, blockType_) + ", block at line " + std::to_string(blockLine_) + ")");
    checkNodes(w[0], v, 1);
  }

  // Nodes of an element line (values from `first` on) against the last $Nodes read.
  void checkNodes(const std::string& element, const std::vector<long long>& v, std::size_t first) {
    if (nodesLine_ == 0) return;
    for (std::size_t k = first; k < v.size(); ++k)
      if (!nodeTags_.count(v[k]))
        return defer("element " + element + " refers to node " + std::to_string(v[k]) +
                     ", which is not defined (expected a node of the $Nodes section at line " +
                     std::to_string(nodesLine_) + ")");
  }

  void close() {
    if (kind_ == Kind::Other || !deferred_.empty()) return;
    const std::string end = "found $End" + section_;
    if (countLine_ == 0)
      return defer(end + " (expected the number of " + what() + "s on the line after $" + section_ + ")");
    if (kind_ == Kind::Nodes22 || kind_ == Kind::Elements22) {
      if (seen_ < count_)
        return defer(end + " after " + plural(seen_, what() + " line") + " (expected " + std::to_string(count_) +
                     ", as announced at line " + std::to_string(countLine_) + ")");
    } else {
      if (blockLeft_ > 0)
        return defer(end + " inside the " + what() + " block at line " + std::to_string(blockLine_) + " (expected " +
                     plural(blockLeft_, "more line") + ")");
      if (blocksSeen_ < blocks_)
        return defer(end + " after " + plural(blocksSeen_, what() + " block") + " (expected " +
                     std::to_string(blocks_) + ", as announced at line " + std::to_string(countLine_) + ")");
      if (itemsSum_ != count_)
        return defer(end + ": the blocks hold " + plural(itemsSum_, what()) + " (expected " + std::to_string(count_) +
                     ", as announced at line " + std::to_string(countLine_) + ")");
    }
    if (nodes()) nodesLine_ = sectionLine_;
  }

  std::string path_;
  std::size_t line_ = 0;
  int version_ = 0;  // 22, 40, 41
  std::string deferred_;
  // The open section.
  std::string section_;
  std::size_t sectionLine_ = 0;
  Kind kind_ = Kind::Other;
  std::size_t countLine_ = 0, count_ = 0, seen_ = 0;
  std::size_t blocks_ = 0, blocksSeen_ = 0, blockLine_ = 0, blockItems_ = 0, blockLeft_ = 0, itemsSum_ = 0;
  int coordinates_ = 3;
  CellType blockType_ = CellType::POI1;
  int blockGmshType_ = 15;
  // Nodes of the last $Nodes section that was read without error (nodesLine_ > 0).
  std::unordered_set<long long> nodeTags_;
  std::size_t nodesLine_ = 0;
};

}  // namespace

void checkMshFile(const std::string& path) { MshChecker(path).run(); }

std::optional<CellType> cellTypeOfGmshElement(int gmshType) {
  for (const auto& p : kGmshTypes)
    if (p.gmsh == gmshType) return p.type;
  return std::nullopt;
}

int gmshElementType(CellType type) {
  for (const auto& p : kGmshTypes)
    if (p.type == type) return p.gmsh;
  // Only TRIA7 is missing from the table.
  throw Error("cell type " + cellTypeName(type) + " cannot be written to gmsh (gmsh has no 7-node triangle)");
}

std::string supportedGmshElementTypes() {
  std::string out;
  for (const auto& p : kGmshTypes)
    out += (out.empty() ? "" : ", ") + std::to_string(p.gmsh) + " (" + cellTypeName(p.type) + ")";
  return out;
}

}  // namespace aster::mesh
