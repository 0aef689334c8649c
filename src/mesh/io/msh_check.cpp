#include "mesh/io/msh_check.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <set>
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

// What is wrong with a line of $PhysicalNames ("" when nothing): the form
// '<dimension> <tag> "<name>"' that gmsh reads, within its 255-byte buffer, and a
// dimension 0 to 3 (gmsh indexes a table with it).
std::string physicalNameError(const std::string& text) {
  std::string line = text;
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
  std::size_t i = 0;
  auto word = [&] {
    while (i < line.size() && isBlank(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !isBlank(line[i])) ++i;
    return line.substr(start, i - start);
  };
  const std::string dim = word(), tag = word();
  while (i < line.size() && isBlank(line[i])) ++i;
  const std::size_t close = line.rfind('"');
  long long d = 0, t = 0;
  bool ok = parseInteger(dim, d) && parseInteger(tag, t) && t >= INT32_MIN && t <= INT32_MAX && i < line.size() &&
            line[i] == '"' && close > i && line.find_first_not_of(" \t", close + 1) == std::string::npos &&
            line.size() < 255;
  for (const char c : line) ok = ok && (static_cast<unsigned char>(c) >= 32 || c == '\t');
  if (!ok)
    return "found " + shown(line) + " (expected a physical name '<dimension> <tag> \"<name>\"' on a line of at most 254 "
           "characters)";
  if (d < 0 || d > 3)
    return "physical name " + shown(line.substr(i)) + " has dimension " + dim + " (expected 0, 1, 2 or 3)";
  return "";
}

// The section gmsh reads where a line starts with "$<name>": it compares the
// beginnings of names only ("$NodesX" is read as $Nodes), in this order, in its
// mesh readers and, when the file holds post-processing data, in its data
// reader. "" when gmsh skips the section.
std::string sectionReadByGmsh(int version, const std::string& name) {
  struct Prefix {
    const char* prefix;
    const char* section;
  };
  static const Prefix k4[] = {{"MeshFormat", "MeshFormat"},
                              {"PhysicalNames", "PhysicalNames"},
                              {"Entities", "Entities"},
                              {"PartitionedEntities", "PartitionedEntities"},
                              {"Nodes", "Nodes"},
                              {"Elements", "Elements"},
                              {"Periodic", "Periodic"},
                              {"GhostElements", "GhostElements"},
                              {"Parametrizations", "Parametrizations"},
                              {"NodeData", "NodeData"},
                              {"ElementData", "ElementData"},
                              {"ElementNodeData", "ElementNodeData"},
                              {"InterpolationScheme", "InterpolationScheme"}};
  static const Prefix k22[] = {{"MeshFormat", "MeshFormat"}, {"PhysicalNames", "PhysicalNames"},
                               {"NO", "Nodes"},              {"Nodes", "Nodes"},
                               {"ParametricNodes", "ParametricNodes"}, {"ELM", "Elements"},
                               {"Elements", "Elements"},     {"Periodic", "Periodic"},
                               {"NodeData", "NodeData"},     {"ElementData", "ElementData"},
                               {"ElementNodeData", "ElementNodeData"}, {"InterpolationScheme", "InterpolationScheme"}};
  const auto read = [&](const auto& table) -> std::string {
    for (const auto& p : table)
      if (name.rfind(p.prefix, 0) == 0) return p.section;
    return "";
  };
  return version == 22 ? read(k22) : read(k4);
}

// gmsh's line buffers: fgets reads at most 1022 bytes and the newline in its MSH 4
// reader, 254 and the newline in its MSH 2 reader and in its data reader.
constexpr std::size_t kShortChunk = 255, kLongChunk = 1023;
// The largest time step of a data section ($NodeData...): gmsh makes an object for
// each time step number up to the one it reads.
constexpr long long kMaxDataStep = 100000;

// A binary .msh file (file type 1), checked in full before gmsh reads it:
// gmsh's binary readers trust every count, tag and size they read (a block
// longer than its section's count overruns their arrays, an unknown element
// type or a cell in an entity of another dimension is kept half-built), so a
// damaged file would crash the program or lose cells instead of failing.
// The file is framed as gmsh frames it: lines are read as fgets reads them, in
// chunks of at most 1023 bytes (255 for MSH 2.2), and a chunk starting with
// '$' opens a section. Offsets in messages are byte offsets from 0.
class BinaryMshChecker {
 public:
  // `start`: the offset just after the version line; `trailer`: what follows
  // "$MeshFormat" on the first line (gmsh expects it after every "$EndName").
  BinaryMshChecker(std::string path, int version, std::ifstream& in, std::uint64_t start, std::string trailer)
      : path_(std::move(path)), version_(version), in_(in), pos_(start), trailer_(std::move(trailer)) {
    in_.clear();
    in_.seekg(0, std::ios::end);
    size_ = static_cast<std::uint64_t>(in_.tellg());
    pos_ = std::min(start, size_);  // a version line without newline ends the file (tellg gave -1)
    in_.seekg(static_cast<std::streamoff>(pos_));
  }

  void run() {
    section_ = "MeshFormat";
    sectionAt_ = 0;
    seen_.insert(section_);
    if (version_ != 22 && version_ != 41)
      fail(pos_, "a binary file of MSH version 4.0 (expected version 4.1 or 2.2 for a binary file; gmsh reads 4.0 "
                 "in ASCII only)");
    const std::uint64_t at = pos_;
    const auto one = read<std::int32_t>("the integer 1 that follows the version line");
    if (one != 1)
      fail(at, "found the binary integer " + std::to_string(one) +
                   " after the version line (expected 1: a file written on a machine of another byte order, or a "
                   "damaged file)");
    endSection("the byte-order integer");
    for (;;) {
      const std::uint64_t at = pos_;
      std::string chunk;
      if (!nextChunk(chunk)) break;
      // gmsh stops when fgets meets the end of the file: on a last line without
      // newline shorter than its buffer. A full chunk without newline is not the
      // end: gmsh reads the next chunk where this one stops.
      if (chunk.back() != '\n' && pos_ == size_ && chunk.size() < chunkSize()) break;
      if (chunk[0] == '$') section(chunk, at);  // other text between sections: gmsh skips it
    }
  }

 private:
  [[noreturn]] void fail(std::uint64_t at, const std::string& what) const {
    throw Error(path_ + ": byte " + std::to_string(at) + " (binary section $" + section_ + " at byte " +
                std::to_string(sectionAt_) + "): " + what);
  }

  std::size_t chunkSize() const { return version_ == 41 ? kLongChunk : kShortChunk; }

  // One line as gmsh's fgets reads it: up to and with '\n', at most 1023 bytes (255 for MSH 2.2).
  bool nextChunk(std::string& chunk) {
    chunk.clear();
    const std::size_t max = chunkSize();
    char c = 0;
    while (chunk.size() < max && pos_ < size_ && in_.get(c)) {
      ++pos_;
      chunk += c;
      if (c == '\n') break;
    }
    return !chunk.empty();
  }

  template <class T>
  T read(const std::string& what) {
    T value{};
    if (size_ - pos_ < sizeof value) fail(pos_, "the file ends inside " + what + " (truncated file?)");
    in_.read(reinterpret_cast<char*>(&value), sizeof value);
    pos_ += sizeof value;
    return value;
  }

  template <class T>
  std::vector<T> readArray(std::uint64_t n, const std::string& what) {
    if (n > (size_ - pos_) / sizeof(T)) fail(pos_, "the file ends inside " + what + " (truncated file?)");
    std::vector<T> values(static_cast<std::size_t>(n));
    in_.read(reinterpret_cast<char*>(values.data()), static_cast<std::streamsize>(n * sizeof(T)));
    pos_ += n * sizeof(T);
    return values;
  }

  // A count of items that take at least `itemBytes` each in what is left of the file.
  std::uint64_t count(std::uint64_t n, std::uint64_t at, const std::string& what, std::uint64_t itemBytes) const {
    const std::uint64_t left = size_ - pos_;
    if (n > left / itemBytes)
      fail(at, what + " is " + std::to_string(n) + ", more than the " + plural(left, "byte") +
                   " left in the file can hold (" + std::to_string(itemBytes) +
                   " bytes or more each): a damaged count or a truncated file");
    return n;
  }
  std::uint64_t readCount(const std::string& what, std::uint64_t itemBytes) {
    const std::uint64_t at = pos_;
    return count(read<std::uint64_t>(what), at, what, itemBytes);
  }
  // MSH 2.2: the count is a text line after the section marker.
  std::uint64_t countLine(const std::string& what, std::uint64_t itemBytes) {
    const std::uint64_t at = pos_;
    std::string chunk;
    long long n = 0;
    const bool got = nextChunk(chunk);
    const auto w = splitWords(chunk);
    if (!got || chunk.back() != '\n' || w.size() != 1 || !parseInteger(w[0], n) || n < 0 || n > INT32_MAX)
      fail(at, "found " + shown(chunk) + " after $" + section_ + " (expected " + what + " on a line of its own)");
    return count(static_cast<std::uint64_t>(n), at, what, itemBytes);
  }

  void section(const std::string& chunk, std::uint64_t at) {
    // The name: printable characters (gmsh would cut a name at a zero byte).
    std::size_t end = 1;
    while (end < chunk.size() && chunk[end] > ' ' && chunk[end] < 127) ++end;
    const std::string name = chunk.substr(1, end - 1);
    section_ = name;
    sectionAt_ = at;
    if (chunk.find_first_not_of(" \t\r\n", end) != std::string::npos)
      fail(at, "found " + shown(chunk) + " (expected a section marker '$Name' alone on its line)");
    sectionTrailer_ = chunk.substr(end);
    if (name.rfind("End", 0) == 0) fail(at, "found $" + name + " outside any section (expected $" + name.substr(3) + " before it)");
    if (!seen_.insert(name).second) fail(at, "a second section $" + name + " (expected one)");
    if (name == "PhysicalNames") {
      physicalNames();
      endSection("the last physical name");
    } else if (name == "Entities" && version_ == 41) {
      entities();
      endSection("the entities");
    } else if (name == "Nodes") {
      version_ == 41 ? nodes41() : nodes22();
      distinct(nodes_, "node");
      nodesAt_ = at;
      endSection("the nodes announced");
    } else if (name == "Elements") {
      version_ == 41 ? elements41() : elements22();
      distinct(elements_, "element");
      endSection("the elements announced");
    } else if (!sectionReadByGmsh(version_, name).empty()) {
      fail(at, std::string("aster-lite does not read section $") + name + " in a binary file (expected the sections " +
                   (version_ == 41 ? "$PhysicalNames, $Entities, $Nodes and $Elements" : "$PhysicalNames, $Nodes and $Elements") +
                   " only; save the mesh as ASCII to keep the others)");
    } else {
      // A section gmsh does not know: it skips chunks up to one whose text after
      // the first byte starts with "End<name>" and the opening marker's trailer.
      const std::string end = "End" + name + sectionTrailer_;
      std::string line;
      for (;;) {
        const std::uint64_t lineAt = pos_;
        if (!nextChunk(line))
          fail(lineAt, "the file ends inside section $" + name + " (expected $End" + name + "; truncated file?)");
        if (line[0] != '$' && line.compare(1, end.size(), end) == 0)
          fail(lineAt, "found " + shown(line) + " inside section $" + name + ", which ends the section for gmsh " +
                           "(expected $End" + name + ")");
        if (line[0] != '$') continue;
        if (line != "$End" + name + sectionTrailer_ && !(pos_ == size_ && isEndAtEof(line)))
          fail(lineAt, "found " + shown(line) + " inside section $" + name + " (expected $End" + name + " first)");
        break;
      }
    }
  }

  bool isEndAtEof(const std::string& line) const {
    const std::string end = "$End" + section_;
    return line.compare(0, end.size(), end) == 0 && line.find_first_not_of(" \t\r", end.size()) == std::string::npos;
  }

  // After a section's content: an optional newline, then "$End<name>" as gmsh
  // expects it (the trailer of the opening marker; none at the end of the file).
  void endSection(const std::string& after) {
    std::uint64_t at = pos_;
    std::string chunk;
    bool got = nextChunk(chunk);
    if (got && chunk == "\n") {
      at = pos_;
      got = nextChunk(chunk);
    }
    const std::string end = "$End" + section_;
    if (got && (chunk == end + (section_ == "MeshFormat" ? trailer_ : sectionTrailer_) ||
                (pos_ == size_ && isEndAtEof(chunk))))
      return;
    if (!got) fail(at, "the file ends after " + after + " (expected " + end + "; truncated file?)");
    fail(at, "found " + shown(chunk) + " after " + after + " (expected " + end +
                 ": a wrong count or size in the section, or a damaged file)");
  }

  // "<count>" then '<dimension> <tag> "<name>"' lines (text, also in a binary file).
  void physicalNames() {
    const std::uint64_t n = countLine("the number of physical names", 7);
    for (std::uint64_t i = 0; i < n; ++i) {
      const std::uint64_t at = pos_;
      std::string chunk;
      if (!nextChunk(chunk) || chunk.back() != '\n')
        fail(at, "the file ends inside physical name " + std::to_string(i + 1) + " of " + std::to_string(n) +
                     " (expected $EndPhysicalNames after them; truncated file?)");
      const std::string wrong = physicalNameError(chunk);
      if (!wrong.empty()) fail(at, wrong);
    }
  }

  // MSH 4.1 $Entities: four counts, then per entity its tag, bounding box,
  // physical tags and (curves, surfaces, volumes) bounding entities.
  void entities() {
    std::uint64_t counts[4];
    for (int d = 0; d < 4; ++d)
      counts[d] = readCount("the number of entities of dimension " + std::to_string(d), d == 0 ? 36 : 68);
    for (int d = 0; d < 4; ++d)
      for (std::uint64_t i = 0; i < counts[d]; ++i) {
        const std::uint64_t at = pos_;
        const std::string what = "entity " + std::to_string(i + 1) + " of dimension " + std::to_string(d);
        const auto tag = read<std::int32_t>("the tag of " + what);
        if (tag < 1) fail(at, what + " has tag " + std::to_string(tag) + " (expected a tag >= 1)");
        if (!declared_.insert({d, tag}).second)
          fail(at, "entity " + std::to_string(tag) + " of dimension " + std::to_string(d) +
                       " is defined twice (expected distinct entity tags)");
        entities_.insert({d, tag});
        readArray<double>(d == 0 ? 3 : 6, "the bounding box of " + what);
        const std::string of = " of entity " + std::to_string(tag) + " of dimension " + std::to_string(d);
        readArray<std::int32_t>(readCount("the number of physical tags" + of, 4), "the physical tags" + of);
        if (d > 0)
          readArray<std::int32_t>(readCount("the number of bounding entities" + of, 4), "the bounding entities" + of);
      }
  }

  static std::string blockText(const char* what, std::uint64_t b) { return std::string(what) + " block " + std::to_string(b); }

  void checkDimension(std::int32_t dim, std::uint64_t at, const std::string& block) const {
    if (dim < 0 || dim > 3)
      fail(at, block + " has entity dimension " + std::to_string(dim) + " (expected 0, 1, 2 or 3)");
  }

  void newNode(std::uint64_t tag, std::uint64_t at, const double* x, int coordinates) {
    if (tag < 1) fail(at, "node tag 0 (expected node tags >= 1)");
    for (int k = 0; k < coordinates; ++k)
      if (!std::isfinite(x[k]))
        fail(at, "node " + std::to_string(tag) + " has a coordinate that is not a finite number (expected finite "
                 "coordinates)");
    nodes_.emplace_back(tag, at);
  }

  void newElement(std::uint64_t tag, std::uint64_t at) {
    if (tag < 1) fail(at, "element tag 0 (expected element tags >= 1)");
    elements_.emplace_back(tag, at);
  }

  // At the end of a section: each tag once (tags sorted, with their offsets: a
  // large file is checked in 16 bytes per node rather than a hash set's 50).
  void distinct(std::vector<std::pair<std::uint64_t, std::uint64_t>>& tags, const char* what) const {
    std::sort(tags.begin(), tags.end());
    for (std::size_t k = 1; k < tags.size(); ++k)
      if (tags[k].first == tags[k - 1].first)
        fail(tags[k].second, std::string(what) + " " + std::to_string(tags[k].first) +
                                 " is defined twice (expected distinct " + what + " tags; the first is at byte " +
                                 std::to_string(tags[k - 1].second) + ")");
  }

  void elementNode(std::uint64_t element, std::uint64_t node, std::uint64_t at) const {
    const auto it = std::lower_bound(nodes_.begin(), nodes_.end(), std::make_pair(node, std::uint64_t{0}));
    if (it == nodes_.end() || it->first != node)
      fail(at, "element " + std::to_string(element) + " refers to node " + std::to_string(node) +
                   ", which is not defined (expected a node of a $Nodes section before $Elements" +
                   (nodesAt_ ? ", at byte " + std::to_string(nodesAt_) : std::string()) + ")");
  }

  // The element type of a block: one aster-lite reads, of the dimension expected.
  CellType blockType(std::int64_t gmshType, std::int32_t dim, std::uint64_t at, const std::string& block) const {
    const auto type = gmshType == static_cast<int>(gmshType) ? cellTypeOfGmshElement(static_cast<int>(gmshType))
                                                             : std::nullopt;
    if (!type) fail(at, block + " has elements of " + unsupportedType(gmshType));
    if (dim >= 0 && topologicalDimension(*type) != dim)
      fail(at, block + " has elements of " + gmshTypeText(static_cast<int>(gmshType), *type) + ", cells of dimension " +
                   std::to_string(topologicalDimension(*type)) + " (expected cells of dimension " +
                   std::to_string(dim) + ", the dimension of their entity)");
    return *type;
  }

  // MSH 4.1 $Nodes: "<blocks> <nodes> <min tag> <max tag>" (size_t), then blocks
  // "<dim> <entity> <parametric>" (int) "<n>" (size_t), n tags, n coordinate sets.
  void nodes41() {
    const std::uint64_t at0 = pos_;
    const std::uint64_t blocks = readCount("the number of node blocks", 20);
    const std::uint64_t total = readCount("the number of nodes", 32);
    read<std::uint64_t>("the smallest node tag");
    read<std::uint64_t>("the largest node tag");
    std::uint64_t sum = 0;
    for (std::uint64_t b = 1; b <= blocks; ++b) {
      const std::uint64_t at = pos_;
      const std::string block = blockText("node", b);
      const auto dim = read<std::int32_t>("the header of " + block);
      const auto entity = read<std::int32_t>("the header of " + block);
      const auto parametric = read<std::int32_t>("the header of " + block);
      checkDimension(dim, at, block);
      if (entity < 1) fail(at, block + " has entity tag " + std::to_string(entity) + " (expected a tag >= 1)");
      if (parametric != 0 && parametric != 1)
        fail(at, block + " has parametric flag " + std::to_string(parametric) + " (expected 0 or 1)");
      entities_.insert({dim, entity});
      const int coordinates = 3 + (parametric ? dim : 0);
      const std::uint64_t n = readCount("the number of nodes of " + block, 8 * (1 + coordinates));
      if (n > total - sum)
        fail(at, block + " holds " + plural(n, "node") + ", more than the " + std::to_string(total) +
                     " announced at byte " + std::to_string(at0 + 8) + " (the blocks before it hold " +
                     std::to_string(sum) + ")");
      sum += n;
      const std::uint64_t tagsAt = pos_;
      const auto tags = readArray<std::uint64_t>(n, "the node tags of " + block);
      const auto xyz = readArray<double>(n * coordinates, "the node coordinates of " + block);
      for (std::uint64_t j = 0; j < n; ++j)
        newNode(tags[j], tagsAt + 8 * j, &xyz[j * coordinates], coordinates);
    }
    if (sum != total)
      fail(at0 + 8, "the node blocks hold " + plural(sum, "node") + " (expected " + std::to_string(total) +
                        ", as announced here)");
  }

  // MSH 4.1 $Elements: "<blocks> <elements> <min tag> <max tag>" (size_t), then
  // blocks "<dim> <entity> <type>" (int) "<n>" (size_t), n x (tag, nodes) (size_t).
  void elements41() {
    const std::uint64_t at0 = pos_;
    const std::uint64_t blocks = readCount("the number of element blocks", 20);
    const std::uint64_t total = readCount("the number of elements", 16);
    read<std::uint64_t>("the smallest element tag");
    read<std::uint64_t>("the largest element tag");
    std::uint64_t sum = 0;
    for (std::uint64_t b = 1; b <= blocks; ++b) {
      const std::uint64_t at = pos_;
      const std::string block = blockText("element", b);
      const auto dim = read<std::int32_t>("the header of " + block);
      const auto entity = read<std::int32_t>("the header of " + block);
      const auto gmshType = read<std::int32_t>("the header of " + block);
      checkDimension(dim, at, block);
      if (!entities_.count({dim, entity}))
        fail(at, block + " is in entity " + std::to_string(entity) + " of dimension " + std::to_string(dim) +
                     ", which is not defined (expected an entity of $Entities or of a node block)");
      const int nn = nodeCount(blockType(gmshType, dim, at, block));
      const std::uint64_t n = readCount("the number of elements of " + block, 8 * (1 + nn));
      if (n > total - sum)
        fail(at, block + " holds " + plural(n, "element") + ", more than the " + std::to_string(total) +
                     " announced at byte " + std::to_string(at0 + 8) + " (the blocks before it hold " +
                     std::to_string(sum) + ")");
      sum += n;
      const std::uint64_t dataAt = pos_;
      const auto data = readArray<std::uint64_t>(n * (1 + nn), "the elements of " + block);
      for (std::uint64_t e = 0; e < n; ++e) {
        const std::uint64_t* v = &data[e * (1 + nn)];
        const std::uint64_t eAt = dataAt + 8 * e * (1 + nn);
        newElement(v[0], eAt);
        for (int k = 1; k <= nn; ++k) elementNode(v[0], v[k], eAt + 8 * k);
      }
    }
    if (sum != total)
      fail(at0 + 8, "the element blocks hold " + plural(sum, "element") + " (expected " + std::to_string(total) +
                        ", as announced here)");
  }

  // Whether "$End<section>" (after an optional newline) starts at byte `at`.
  bool endMarkerAt(std::uint64_t at) {
    const std::string end = "$End" + section_;
    std::string bytes(end.size() + 1, '\0');
    in_.seekg(static_cast<std::streamoff>(at));
    in_.read(&bytes[0], static_cast<std::streamsize>(bytes.size()));
    bytes.resize(static_cast<std::size_t>(in_.gcount()));
    in_.clear();
    in_.seekg(static_cast<std::streamoff>(pos_));
    return bytes.compare(0, end.size(), end) == 0 || bytes == "\n" + end;
  }

  // MSH 2.2 $Nodes: "<count>" (text), then count x (tag (int), x y z (double)).
  void nodes22() {
    const std::uint64_t countAt = pos_;
    const std::uint64_t n = countLine("the number of nodes", 28);
    // Records of a fixed size: a wrong count is seen where they end.
    if (!endMarkerAt(pos_ + 28 * n))
      fail(countAt, std::to_string(n) + " nodes of 28 bytes announced, but $EndNodes does not follow them at byte " +
                        std::to_string(pos_ + 28 * n) + " (expected the number of nodes of the section: a wrong count "
                        "or a damaged file)");
    for (std::uint64_t i = 0; i < n; ++i) {
      const std::uint64_t at = pos_;
      const auto tag = read<std::int32_t>("the tag of node line " + std::to_string(i + 1));
      const auto xyz = readArray<double>(3, "the coordinates of node line " + std::to_string(i + 1));
      if (tag < 0) fail(at, "node tag " + std::to_string(tag) + " (expected node tags >= 1)");
      newNode(static_cast<std::uint64_t>(tag), at, xyz.data(), 3);
    }
  }

  // MSH 2.2 $Elements: "<count>" (text), then blocks "<type> <n> <number of
  // tags>" (int), n x (tag, tags, nodes) (int), until count elements are read.
  void elements22() {
    const std::uint64_t countAt = pos_;
    const std::uint64_t total = countLine("the number of elements", 8);
    std::uint64_t sum = 0;
    for (std::uint64_t b = 1; sum < total; ++b) {
      const std::uint64_t at = pos_;
      const std::string block = blockText("element", b);
      const auto gmshType = read<std::int32_t>("the header of " + block);
      const auto n = read<std::int32_t>("the header of " + block);
      const auto tags = read<std::int32_t>("the header of " + block);
      const int nn = nodeCount(blockType(gmshType, -1, at, block));
      if (tags < 0 || tags > 2)
        fail(at, block + " has " + std::to_string(tags) +
                     " tags per element (expected 0 to 2: physical and elementary; aster-lite does not read "
                     "partitioned binary MSH 2.2 files)");
      if (n < 1 || static_cast<std::uint64_t>(n) > total - sum)
        fail(at, block + " holds " + std::to_string(n) + " elements (expected 1 to " + std::to_string(total - sum) +
                     ": " + std::to_string(total) + " announced at byte " + std::to_string(countAt) +
                     ", the blocks before it hold " + std::to_string(sum) + ")");
      const std::uint64_t width = 1 + static_cast<std::uint64_t>(tags) + nn;
      count(static_cast<std::uint64_t>(n), at + 4, "the number of elements of " + block, 4 * width);
      sum += static_cast<std::uint64_t>(n);
      const std::uint64_t dataAt = pos_;
      const auto data = readArray<std::int32_t>(static_cast<std::uint64_t>(n) * width, "the elements of " + block);
      for (std::uint64_t e = 0; e < static_cast<std::uint64_t>(n); ++e) {
        const std::int32_t* v = &data[e * width];
        const std::uint64_t eAt = dataAt + 4 * e * width;
        if (v[0] < 0) fail(eAt, "element tag " + std::to_string(v[0]) + " (expected element tags >= 1)");
        newElement(static_cast<std::uint64_t>(v[0]), eAt);
        for (std::uint64_t k = 1 + tags; k < width; ++k)
          if (v[k] < 1)
            fail(eAt + 4 * k, "element " + std::to_string(v[0]) + " refers to node " + std::to_string(v[k]) +
                                  " (expected node tags >= 1)");
          else
            elementNode(static_cast<std::uint64_t>(v[0]), static_cast<std::uint64_t>(v[k]), eAt + 4 * k);
      }
    }
  }

  std::string path_;
  int version_;
  std::ifstream& in_;
  std::uint64_t pos_ = 0, size_ = 0;
  std::string trailer_;
  // The section being read.
  std::string section_, sectionTrailer_;
  std::uint64_t sectionAt_ = 0;
  std::set<std::string> seen_;
  std::set<std::pair<int, int>> declared_, entities_;  // (dim, tag): of $Entities; of $Entities and node blocks
  std::vector<std::pair<std::uint64_t, std::uint64_t>> nodes_, elements_;  // (tag, offset), sorted once complete
  std::uint64_t nodesAt_ = 0;
};

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
    const std::string firstLine = line;
    headerLength(line);
    const char* headerForm = "'<version> <file-type> <data-size>', e.g. '4.1 0 8'";
    if (!std::getline(in, line))
      fail(line_, std::string("the file ends after $MeshFormat (expected ") + headerForm + ")");
    ++line_;
    headerLength(line);
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
    if (fileType == 1) {
      // gmsh expects "$EndMeshFormat" followed by what followed "$MeshFormat".
      const std::string trailer = firstLine.substr(std::string("$MeshFormat").size()) + "\n";
      return BinaryMshChecker(path_, version_, in, static_cast<std::uint64_t>(in.tellg()), trailer).run();
    }

    open("MeshFormat", first);
    while (std::getline(in, line)) {
      ++line_;
      pieces(line);
      const auto w = splitWords(line);
      if (w.empty()) continue;
      if (w[0][0] == '$' && section_ == "Comments" && w[0] != "$EndComments") {
        comment(w[0]);
      } else if (w[0][0] == '$') {
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
  enum class Kind { Other, Names, Nodes22, Elements22, Nodes41, Elements41, Data, Scheme, Entities };

  [[noreturn]] void fail(std::size_t line, const std::string& what) const {
    throw Error(path_ + ":" + std::to_string(line) + ": " + what);
  }

  // gmsh reads the two header lines with buffers of 255 bytes: a longer line
  // would be read in pieces, the next piece as the version line.
  void headerLength(const std::string& line) const {
    if (line.size() >= kShortChunk)
      fail(line_, "found a header line of " + plural(line.size(), "byte") + " (expected at most " +
                      std::to_string(kShortChunk - 1) + ")");
  }

  // gmsh reads a line longer than its buffer in pieces (of 255 or 1023 bytes),
  // and a piece that starts with '$' is a section marker to it: such a line may
  // hold '$' only as its first byte.
  void pieces(const std::string& line) const {
    if (line.size() < kShortChunk) return;
    const std::size_t dollar = line.find('$', 1);
    if (dollar != std::string::npos)
      fail(line_, "found a line of " + plural(line.size(), "byte") + " with a '$' at column " +
                      std::to_string(dollar + 1) + " (expected '$' only at the start of a line longer than " +
                      std::to_string(kShortChunk - 1) + " bytes: gmsh reads such a line in pieces, and a piece "
                      "starting with '$' would open a section)");
  }

  // A '$' line inside $Comments: text, unless gmsh reads a section of its name
  // there (its MSH 2 reader does not skip comments; its data reader neither).
  void comment(const std::string& raw) const {
    const std::string as = sectionReadByGmsh(version_, raw.substr(1));
    if (!as.empty())
      fail(line_, "found " + escaped(raw) + " inside section $Comments opened at line " +
                      std::to_string(sectionLine_) + " (expected $EndComments first: gmsh reads $" + as +
                      " there)");
  }
  // An error on a line inside a section: reported when the structure is sound.
  void defer(const std::string& what) {
    if (deferred_.empty()) deferred_ = path_ + ":" + std::to_string(line_) + ": " + what;
  }

  void open(const std::string& name, std::size_t line) {
    section_ = name;
    sectionLine_ = line;
    kind_ = Kind::Other;
    if (name == "PhysicalNames") kind_ = Kind::Names;
    if (name == "Nodes" && version_ == 22) kind_ = Kind::Nodes22;
    if (name == "Elements" && version_ == 22) kind_ = Kind::Elements22;
    if (name == "Nodes" && version_ >= 40) kind_ = Kind::Nodes41;
    if (name == "Elements" && version_ >= 40) kind_ = Kind::Elements41;
    if (name == "NodeData" || name == "ElementData" || name == "ElementNodeData") kind_ = Kind::Data;
    if (name == "InterpolationScheme") kind_ = Kind::Scheme;
    if (name == "Entities" && version_ >= 40) kind_ = Kind::Entities;
    data_ = DataHeader{};
    schemeWords_.clear();
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
    const std::string as = sectionReadByGmsh(version_, raw.substr(1));
    if (!as.empty() && as != raw.substr(1))
      fail(line_, "found " + word + ", which gmsh reads as section $" + as +
                      " (it compares the beginnings of section names; expected $" + as + ")");
    if (version_ >= 40 && (as == "PartitionedEntities" || as == "Periodic" || as == "GhostElements" ||
                           as == "Parametrizations"))
      fail(line_, "found " + word + ", a section aster-lite does not read and in which gmsh trusts the sizes it "
                  "reads (expected $PhysicalNames, $Entities, $Nodes, $Elements and data sections only)");
    if (as == "MeshFormat")
      fail(line_, "found a second section $MeshFormat (expected one: gmsh would read the file type again, and the "
                  "rest of the file as binary if it says so)");
    open(word.substr(1), line_);
  }

  // ---- Lines inside a section ----

  void content(const std::string& line, const std::vector<std::string>& w) {
    if (!deferred_.empty()) return;
    switch (kind_) {
      case Kind::Other:
        return;
      case Kind::Data:
        return contentData(line, w);
      case Kind::Entities: {
        // "<points> <curves> <surfaces> <volumes>", then a line per entity (left
        // to gmsh, which sizes a line buffer of 128 bytes per entity announced).
        std::vector<long long> v;
        if (countLine_ == 0) {
          if (!parseIntegers(w, v, 4) || w.size() != 4 || v[0] < 0 || v[1] < 0 || v[2] < 0 || v[3] < 0 ||
              v[0] + v[1] + v[2] + v[3] > INT32_MAX)
            return defer("found " + shown(line) + " after $Entities (expected '<points> <curves> <surfaces> <volumes>')");
          countLine_ = line_;
          count_ = static_cast<std::size_t>(v[0] + v[1] + v[2] + v[3]);
          return;
        }
        ++seen_;
        return;
      }
      case Kind::Scheme:
        if (countLine_ == 0) {  // the name, read with a 255-byte buffer
          countLine_ = line_;
          if (line.size() >= kShortChunk) defer("found a line of " + plural(line.size(), "byte") + " (expected a scheme name of at most 254)");
          return;
        }
        schemeWords_.insert(schemeWords_.end(), w.begin(), w.end());
        return;
      case Kind::Names:
        return contentNames(line, w);
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

  // "<count>" then count lines '<dimension> <tag> "<name>"'.
  void contentNames(const std::string& line, const std::vector<std::string>& w) {
    long long n = 0;
    if (countLine_ == 0) {
      if (w.size() != 1 || !parseInteger(w[0], n) || n < 0 || n > INT32_MAX)
        return defer("found " + shown(line) + " after $PhysicalNames (expected the number of physical names)");
      countLine_ = line_;
      count_ = static_cast<std::size_t>(n);
      return;
    }
    if (++seen_ > count_)
      return defer("found " + shown(line) + ", one physical name more than the " + std::to_string(count_) +
                   " announced at line " + std::to_string(countLine_) + " (expected $EndPhysicalNames)");
    const std::string wrong = physicalNameError(line);
    if (!wrong.empty()) defer(wrong);
  }

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
      maxNodeTag_ = std::max(maxNodeTag_, n);
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
    maxElementTag_ = std::max(maxElementTag_, v[0]);
    checkNodes(w[0], v, static_cast<std::size_t>(3 + v[2]));
  }

  // MSH 4.1: "<blocks> <count> <min tag> <max tag>", then blocks of
  // "<dim> <entity> <parametric|type> <n>" followed by n lines (2 n for nodes).
  // MSH 4.0: "<blocks> <count>", block headers "<entity tag> <entity dim> ...",
  // nodes "<tag> <coordinates>" on one line.
  void content41(const std::string& line, const std::vector<std::string>& w) {
    std::vector<long long> v;
    const bool v40 = version_ == 40;
    const std::size_t dim = v40 ? 1 : 0;  // where the entity dimension is in a block header
    if (countLine_ == 0) {
      const std::size_t words = v40 ? 2 : 4;
      if (!parseIntegers(w, v, words) || w.size() != words || v[0] < 0 || v[1] < 0)
        return defer("found " + shown(line) + " after $" + section_ + " (expected '<blocks> <" + what() +
                     (v40 ? "s>')" : "s> <min tag> <max tag>')"));
      countLine_ = line_;
      blocks_ = static_cast<std::size_t>(v[0]);
      count_ = static_cast<std::size_t>(v[1]);
      return;
    }
    if (blockLeft_ == 0) {  // a block header
      if (blocksSeen_ == blocks_)
        return defer("found " + shown(line) + " after the " + plural(blocks_, what() + " block") +
                     " announced at line " + std::to_string(countLine_) + " (expected $End" + section_ + ")");
      const std::string entity = v40 ? "'<entity tag> <entity dim>" : "'<entity dim> <entity tag>";
      const std::string form = entity + (nodes() ? " <parametric> <nodes in block>'" : " <element type> <elements in block>'");
      if (!parseIntegers(w, v, 4) || w.size() != 4 || v[dim] < 0 || v[dim] > 3 || v[3] < 0)
        return defer("found " + shown(line) + " (expected a " + what() + " block header " + form + ")");
      ++blocksSeen_;
      blockLine_ = line_;
      blockItems_ = static_cast<std::size_t>(v[3]);
      itemsSum_ += blockItems_;
      if (nodes()) {
        if (v[2] != 0 && v[2] != 1)
          return defer("found " + shown(line) + " (expected a node block header " + form + ", parametric 0 or 1)");
        coordinates_ = 3 + (v[2] == 1 ? static_cast<int>(v[dim]) : 0);
        blockLeft_ = (v40 ? 1 : 2) * blockItems_;
      } else {
        const auto type = cellTypeOfGmshElement(static_cast<int>(v[2]));
        blockLeft_ = blockItems_;
        // MSH 4.0: a type code_aster lacks is left to gmsh and reported after it.
        anyType_ = v40 && !type;
        if (anyType_) return;
        if (v[2] != static_cast<int>(v[2]) || !type)
          return defer("the elements of entity " + w[1 - dim] + " (dimension " + w[dim] + ") have " +
                       unsupportedType(v[2]));
        blockType_ = *type;
        blockGmshType_ = static_cast<int>(v[2]);
      }
      return;
    }
    --blockLeft_;
    if (nodes()) {
      long long tag = 0;
      if (v40) {  // "<tag> <coordinates>"
        double x = 0;
        bool ok = static_cast<int>(w.size()) == 1 + coordinates_ && parseInteger(w[0], tag) && tag >= 1;
        for (std::size_t k = 1; ok && k < w.size(); ++k) ok = parseReal(w[k], x);
        if (!ok)
          return defer("found " + shown(line) + " (expected a node line '<tag> <x> <y> <z>'" +
                       (coordinates_ > 3 ? " and its parametric coordinates" : "") + ", block at line " +
                       std::to_string(blockLine_) + ")");
        nodeTags_.insert(tag);
        maxNodeTag_ = std::max(maxNodeTag_, tag);
        return;
      }
      if (blockLeft_ >= blockItems_) {  // the tags come first, one per line
        if (w.size() != 1 || !parseInteger(w[0], tag) || tag < 1)
          return defer("found " + shown(line) + " (expected a node tag of the block at line " +
                       std::to_string(blockLine_) + ")");
        nodeTags_.insert(tag);
        maxNodeTag_ = std::max(maxNodeTag_, tag);
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
    if (anyType_) {
      if (!parseIntegers(w, v, 2))
        return defer("found " + shown(line) + " (expected an element tag and its nodes, block at line " +
                     std::to_string(blockLine_) + ")");
      maxElementTag_ = std::max(maxElementTag_, v[0]);
      return;
    }
    const int nn = nodeCount(blockType_);
    if (!parseIntegers(w, v, 1) || static_cast<int>(v.size()) != 1 + nn)
      return defer("found " + shown(line) + " (expected an element tag and " + std::to_string(nn) + " nodes: " +
                   gmshTypeText(blockGmshType_, blockType_) + ", block at line " + std::to_string(blockLine_) + ")");
    maxElementTag_ = std::max(maxElementTag_, v[0]);
    checkNodes(w[0], v, 1);
  }

  // $NodeData, $ElementData, $ElementNodeData, read by gmsh's data reader: lines
  // "<n>" and n string tags, "<n>" and n real tags, "<n>" and n integer tags (time
  // step, components, entities, ...), each read whole with a 255-byte buffer; then a
  // line per entity "<tag> [<values per entity>] <values>". gmsh makes a time step
  // object for each step number up to the one read and sizes its data tables by
  // the largest entity tag: both are bounded here.
  void contentData(const std::string& line, const std::vector<std::string>& w) {
    DataHeader& d = data_;
    const std::string where = " in $" + section_ + " (line " + std::to_string(sectionLine_) + ")";
    long long n = 0;
    double x = 0;
    if (d.phase < 6 && line.size() >= kShortChunk)
      return defer("found a header line of " + plural(line.size(), "byte") + where + " (expected at most " +
                   std::to_string(kShortChunk - 1) + ")");
    switch (d.phase) {
      case 0:
      case 2:
      case 4: {
        const char* tags[] = {"string", "", "real", "", "integer"};
        const long long least = d.phase == 4 ? 3 : 0;
        if (w.size() != 1 || !parseInteger(w[0], n) || n < least || n > INT32_MAX)
          return defer("found " + shown(line) + where + " (expected the number of " + tags[d.phase] + " tags" +
                       (least ? ", 3 or more: time step, components, entities)" : ")"));
        d.left = n;
        d.phase = n > 0 ? d.phase + 1 : d.phase + 2;
        return;
      }
      case 1:
      case 3:
      case 5:
        if (d.phase == 3 && (w.size() != 1 || !parseReal(w[0], x)))
          return defer("found " + shown(line) + where + " (expected a real tag, one number)");
        if (d.phase == 5) {
          if (w.size() != 1 || !parseInteger(w[0], n) || n < INT32_MIN || n > INT32_MAX)
            return defer("found " + shown(line) + where + " (expected an integer tag, one integer)");
          d.ints.push_back(n);
        }
        if (--d.left > 0) return;
        ++d.phase;
        if (d.phase == 6) {
          if (d.ints[0] < 0 || d.ints[0] > kMaxDataStep)
            return defer("time step " + std::to_string(d.ints[0]) + where + " (expected 0 to " +
                         std::to_string(kMaxDataStep) + ")");
          if (d.ints[1] < 1) return defer(std::to_string(d.ints[1]) + " components" + where + " (expected 1 or more)");
          if (d.ints[2] < 0) return defer(std::to_string(d.ints[2]) + " entities" + where + " (expected 0 or more)");
          d.left = d.ints[2];
        }
        return;
      default:
        break;
    }
    if (d.left == 0)
      return defer("found " + shown(line) + where + ", one line more than the " + std::to_string(d.ints[2]) +
                   " entities announced (expected $End" + section_ + ")");
    --d.left;
    const bool nodes = section_ == "NodeData", perNode = section_ == "ElementNodeData";
    const long long largest = nodes ? maxNodeTag_ : maxElementTag_;
    const char* entity = nodes ? "node" : "element";
    long long tag = 0, mult = 1;
    if (w.empty() || !parseInteger(w[0], tag) || tag < 0 || tag > largest)
      return defer("found " + shown(line) + where + " (expected a " + entity + " tag 0 to " +
                   std::to_string(largest) + ", the largest of the file so far, then its values)");
    if (perNode && (w.size() < 2 || !parseInteger(w[1], mult) || mult < 1 || mult > 27))
      return defer("found " + shown(line) + where + " (expected an element tag, its number of nodes, 1 to 27, then "
                   "its values)");
    const std::size_t first = perNode ? 2 : 1;
    const long long values = mult * d.ints[1];
    bool ok = static_cast<long long>(w.size() - first) == values;
    for (std::size_t k = first; ok && k < w.size(); ++k) ok = parseReal(w[k], x);
    if (!ok)
      return defer("found " + shown(line) + where + " (expected " + std::to_string(values) + " numbers after the " +
                   entity + " tag" + (perNode ? " and its number of nodes)" : ")"));
  }

  // $InterpolationScheme, read by gmsh's data reader: a name line, then the
  // numbers "<types>" and per type "<type> <matrices>", per matrix "<m> <n>" and
  // m n reals, in any line layout. gmsh sizes each matrix as announced.
  void closeScheme() {
    const std::string where = "found $EndInterpolationScheme (section at line " + std::to_string(sectionLine_) + ")";
    std::size_t i = 0;
    auto integer = [&](const char* what) {
      long long n = 0;
      if (!deferred_.empty()) return n;
      if (i >= schemeWords_.size() || !parseInteger(schemeWords_[i], n) || n < 0 || n > INT32_MAX)
        defer(where + ": " + (i >= schemeWords_.size() ? "the numbers end" : "found '" + escaped(schemeWords_[i]) + "'") +
              " where " + what + " is expected (an integer 0 or more)");
      ++i;
      return n;
    };
    const long long types = integer("the number of element types");
    for (long long t = 0; t < types && deferred_.empty(); ++t) {
      integer("an element type");
      const long long matrices = integer("a number of matrices");
      for (long long k = 0; k < matrices && deferred_.empty(); ++k) {
        const long long m = integer("a number of rows"), n = integer("a number of columns");
        if (!deferred_.empty()) return;
        const std::size_t left = schemeWords_.size() - i;
        double x = 0;
        if (n > 0 && m > static_cast<long long>(left) / n)
          return defer(where + ": a matrix of " + std::to_string(m) + " x " + std::to_string(n) + " with " +
                       plural(left, "number") + " left (expected the numbers of the matrices announced)");
        for (long long v = 0; v < m * n; ++v, ++i)
          if (!parseReal(schemeWords_[i], x))
            return defer(where + ": found '" + escaped(schemeWords_[i]) + "' in a matrix (expected a number)");
      }
    }
    if (deferred_.empty() && i < schemeWords_.size())
      defer(where + ": " + plural(schemeWords_.size() - i, "number") + " more than its matrices hold");
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
    if (kind_ == Kind::Scheme) return closeScheme();
    if (kind_ == Kind::Entities) {
      if (countLine_ == 0) return defer("found $EndEntities (expected the numbers of entities on the line after $Entities)");
      if (seen_ != count_)
        defer("found $EndEntities after " + plural(seen_, "entity line") + " (expected " + std::to_string(count_) +
              ", as announced at line " + std::to_string(countLine_) + ")");
      return;
    }
    if (kind_ == Kind::Data) {
      if (data_.phase < 6 || data_.left > 0)
        defer("found $End" + section_ + " (expected " +
              (data_.phase < 6 ? std::string("the tags of the section at line ") + std::to_string(sectionLine_)
                               : plural(static_cast<std::size_t>(data_.left), "more entity line")) +
              ")");
      return;
    }
    const std::string end = "found $End" + section_;
    if (kind_ == Kind::Names) {
      if (countLine_ == 0) return defer(end + " (expected the number of physical names on the line after $PhysicalNames)");
      if (seen_ < count_)
        return defer(end + " after " + plural(seen_, "physical name") + " (expected " + std::to_string(count_) +
                     ", as announced at line " + std::to_string(countLine_) + ")");
      return;
    }
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
  bool anyType_ = false;  // an element block of MSH 4.0 of a type code_aster lacks
  // Nodes of the last $Nodes section that was read without error (nodesLine_ > 0).
  std::unordered_set<long long> nodeTags_;
  std::size_t nodesLine_ = 0;
  long long maxNodeTag_ = 0, maxElementTag_ = 0;  // of the whole file so far
  // A data section being read: its phase (0 string tag count, 1 string tags, 2 real
  // count, 3 reals, 4 integer count, 5 integers, 6 entity lines) and what is left.
  struct DataHeader {
    int phase = 0;
    long long left = 0;
    std::vector<long long> ints;
  };
  DataHeader data_;
  std::vector<std::string> schemeWords_;
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
