#include "mesh/io/aster_format.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <ostream>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "core/suggest.hpp"

namespace aster::mesh {

namespace {

struct Token {
  std::string_view text;
  int line;
};

std::string upper(std::string_view s) {
  std::string u(s);
  for (char& c : u) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return u;
}

bool sameWord(std::string_view s, const char* keyword) {  // case-insensitive
  const std::size_t n = std::strlen(keyword);
  if (s.size() != n) return false;
  for (std::size_t i = 0; i < n; ++i)
    if (std::toupper(static_cast<unsigned char>(s[i])) != keyword[i]) return false;
  return true;
}

bool isBlankChar(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// The next word of `line` from `pos`. With `equalsSeparates`, '=' ends a word
// and is skipped as a blank (code_aster reads "M2 = N1 N2" as "M2 N1 N2").
bool nextWord(std::string_view line, std::size_t& pos, std::string_view& word, bool equalsSeparates) {
  auto blank = [&](char c) { return isBlankChar(c) || (equalsSeparates && c == '='); };
  while (pos < line.size() && blank(line[pos])) ++pos;
  if (pos >= line.size()) return false;
  const std::size_t start = pos;
  while (pos < line.size() && !blank(line[pos])) ++pos;
  word = line.substr(start, pos - start);
  return true;
}

std::string_view firstWord(std::string_view line) {
  std::size_t pos = 0;
  std::string_view w;
  return nextWord(line, pos, w, false) ? w : std::string_view();
}

// Header-line keys that only describe the section (written by code_aster's
// interfaces: PRE_GMSH, IDEAS...); they change nothing in what is read.
bool isInformativeKey(const std::string& key) {
  for (const char* k : {"INFO", "NBOBJ", "NOBJ", "NBLIGE", "NBLIGT", "NUMIN", "NUMAX", "AUTEUR", "DATE"})
    if (key == k) return true;
  return false;
}

struct PendingCell {
  CellType type;
  Token name;
  std::size_t firstNode;  // into AsterParser::cellNodes_
};

struct PendingGroup {
  bool ofCells;
  std::string name;
  int line;
  std::vector<Token> members;
};

// What the header line of a section says.
struct Header {
  std::string groupName;  // NOM= (GROUP_MA, GROUP_NO)
  std::string ignoredText;  // words that are no KEY=VALUE (GROUP_MA, GROUP_NO)
  int headerLines = 1;  // NBLIGE=: the header spans that many lines
};

class AsterParser {
 public:
  AsterParser(const std::string& text, std::string source, std::vector<std::string>* alarms)
      : source_(std::move(source)), alarms_(alarms) {
    std::size_t begin = 0;
    while (begin < text.size()) {
      std::size_t end = text.find('\n', begin);
      if (end == std::string::npos) end = text.size();
      std::string_view line(text.data() + begin, end - begin);
      // A text mesh holds no control characters: say so rather than quoting binary bytes.
      for (std::size_t c = 0; c < line.size(); ++c) {
        const unsigned char b = static_cast<unsigned char>(line[c]);
        if ((b < 32 && b != '\t' && b != '\r' && b != '\f' && b != '\v') || b == 127) {
          char hex[8];
          std::snprintf(hex, sizeof hex, "0x%02x", b);
          throw Error(source_ + ":" + std::to_string(lines_.size() + 1) + ": binary byte " + hex + " at column " +
                      std::to_string(c + 1) + ": this is not an ASTER text mesh (.mail)");
        }
      }
      const auto pct = line.find('%');
      if (pct != std::string_view::npos) line = line.substr(0, pct);
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      lines_.push_back(line);
      begin = end + 1;
    }
  }

  Mesh parse() {
    std::size_t i = 0;
    while (i < lines_.size() && !finished_) {
      const std::string_view first = firstWord(lines_[i]);
      if (first.empty()) {
        ++i;
        continue;
      }
      const int headerLine = static_cast<int>(i) + 1;
      const std::string keyword = upper(first);
      if (keyword == "FIN") {
        finished_ = true;
        break;
      }
      if (keyword == "FINSF") {  // a section closed twice: code_aster skips the extra FINSF
        ++i;
        continue;
      }
      checkKeyword(keyword, headerLine);
      if (keyword == "TITRE") {  // code_aster ignores the rest of the TITRE line
        ++i;
        readTitle(i, headerLine);
        continue;
      }
      const bool group = keyword == "GROUP_MA" || keyword == "GROUP_NO";
      const Header header = readHeader(lines_[i], group, headerLine);
      i += static_cast<std::size_t>(header.headerLines);
      const auto body = sectionTokens(i, keyword, headerLine);
      if (keyword.rfind("COOR_", 0) == 0)
        readCoordinates(body, keyword[5] - '0');
      else if (group)
        readGroup(body, keyword == "GROUP_MA", header, headerLine);
      else
        readCells(body, cellTypeFromName(keyword));
    }
    if (!finished_ && lines_.empty()) throw Error(source_ + ": the file is empty (expected an ASTER mesh ended by FIN)");
    if (!finished_)
      throw Error(source_ + ":" + std::to_string(lines_.size()) +
                  ": the file ends without FIN (truncated file?)");
    return build();
  }

 private:
  [[noreturn]] void fail(int line, const std::string& what) const {
    throw Error(source_ + ":" + std::to_string(line) + ": " + what);
  }
  [[noreturn]] void truncated(const std::string& section, int line) const {
    fail(static_cast<int>(lines_.size()),
         "the file ends inside section " + section + " opened at line " + std::to_string(line) +
             " (expected FINSF, truncated file?)");
  }
  void alarm(int line, const std::string& what) const {
    if (alarms_) alarms_->push_back(source_ + ":" + std::to_string(line) + ": " + what);
  }

  void checkKeyword(const std::string& keyword, int line) const {
    if (keyword == "TITRE" || keyword == "COOR_1D" || keyword == "COOR_2D" || keyword == "COOR_3D" ||
        keyword == "GROUP_MA" || keyword == "GROUP_NO" || isCellTypeName(keyword))
      return;
    std::vector<std::string> known{"TITRE", "COOR_1D", "COOR_2D", "COOR_3D", "GROUP_MA", "GROUP_NO", "FIN"};
    for (int t = 0; t < kCellTypeCount; ++t) known.push_back(cellTypeName(static_cast<CellType>(t)));
    const std::string hint = didYouMean(keyword, known);
    fail(line, "unknown section or cell type '" + keyword + "'" + (hint.empty() ? "" : ";" + hint) +
                   " (expected TITRE, COOR_1D, COOR_2D, COOR_3D, a cell type such as QUAD8, GROUP_MA, GROUP_NO or FIN)");
  }

  // Title lines up to FINSF (or FIN, which also ends the file, as in code_aster).
  void readTitle(std::size_t& i, int headerLine) {
    std::string title;
    while (true) {
      if (i >= lines_.size()) truncated("TITRE", headerLine);
      const std::string_view line = lines_[i++];
      const std::string_view first = firstWord(line);
      if (sameWord(first, "FINSF")) break;
      if (sameWord(first, "FIN")) {
        finished_ = true;
        break;
      }
      const auto b = line.find_first_not_of(" \t");
      if (b == std::string_view::npos) continue;
      const auto e = line.find_last_not_of(" \t");
      title += (title.empty() ? "" : "\n") + std::string(line.substr(b, e - b + 1));
    }
    mesh_.title = title;
  }

  // The words after the section keyword: KEY=VALUE items ("KEY = VALUE" alike)
  // and free words. As code_aster: NOM= names a group; NBLIGE=n says the header
  // spans n lines (the n-1 after the keyword line are skipped, whatever they
  // hold); everything else only describes the section and is ignored, except
  // that a group line refuses an unknown key (a misspelt NOM= would otherwise
  // take the group's name from the next line).
  Header readHeader(std::string_view line, bool group, int lineNo) const {
    std::vector<std::string_view> items;  // words, with each '=' an item of its own
    std::size_t pos = 0;
    std::string_view w;
    nextWord(line, pos, w, false);  // the keyword
    while (nextWord(line, pos, w, false)) {
      while (!w.empty()) {
        const auto eq = w.find('=');
        if (eq == std::string_view::npos) {
          items.push_back(w);
          break;
        }
        if (eq > 0) items.push_back(w.substr(0, eq));
        items.push_back("=");
        w.remove_prefix(eq + 1);
      }
    }
    Header h;
    std::vector<std::string> freeWords;
    for (std::size_t k = 0; k < items.size(); ++k) {
      if (items[k] == "=") continue;  // a value-less '=': nothing to read
      if (k + 1 >= items.size() || items[k + 1] != "=") {
        freeWords.emplace_back(items[k]);
        continue;
      }
      const std::string key = upper(items[k]);
      std::string value;
      if (k + 2 < items.size() && items[k + 2] != "=") value = std::string(items[k + 2]);
      k += value.empty() ? 1 : 2;
      if (value.size() >= 2 && (value.front() == '\'' || value.front() == '"')) value = value.substr(1, value.size() - 2);
      if (key == "NBLIGE") {
        char* end = nullptr;
        const long n = std::strtol(value.c_str(), &end, 10);
        if (value.empty() || *end != '\0' || n < 0 || n > 1000)
          fail(lineNo, "NBLIGE= needs the number of lines of the section's header, got '" + value + "'");
        h.headerLines = n > 1 ? static_cast<int>(n) : 1;
      }
      if (!group) continue;  // TITRE, COOR_nD and cell lines: no key has a meaning
      if (key == "NOM") {
        if (value.empty()) fail(lineNo, "NOM= needs a group name");
        h.groupName = value;
      } else if (!isInformativeKey(key)) {
        fail(lineNo, "unknown option '" + key + "' on a section line (expected NOM= or INFO=)");
      }
    }
    if (group && h.groupName.empty() && !freeWords.empty())
      h.ignoredText = joinNames(freeWords);
    return h;
  }

  // The words of a section up to FINSF; FIN first on a line also closes the
  // section and ends the file (code_aster accepts it).
  std::vector<Token> sectionTokens(std::size_t& i, const std::string& section, int headerLine) {
    std::vector<Token> tokens;
    while (true) {
      if (i >= lines_.size()) truncated(section, headerLine);
      const int lineNo = static_cast<int>(i) + 1;
      const std::string_view line = lines_[i++];
      std::size_t pos = 0;
      std::string_view w;
      bool firstOfLine = true;
      while (nextWord(line, pos, w, true)) {
        if (sameWord(w, "FINSF")) {
          if (nextWord(line, pos, w, true)) fail(lineNo, "unexpected text '" + std::string(w) + "' after FINSF");
          return tokens;
        }
        if (firstOfLine && sameWord(w, "FIN")) {
          finished_ = true;
          return tokens;
        }
        firstOfLine = false;
        tokens.push_back({w, lineNo});
      }
    }
  }

  double number(const Token& t, const std::string_view nodeName, int coordinate) const {
    char buffer[64];
    const bool fits = !t.text.empty() && t.text.size() < sizeof buffer;
    if (fits) {
      for (std::size_t k = 0; k < t.text.size(); ++k) buffer[k] = (t.text[k] == 'D' || t.text[k] == 'd') ? 'E' : t.text[k];
      buffer[t.text.size()] = '\0';
      errno = 0;
      char* end = nullptr;
      const double v = std::strtod(buffer, &end);
      if (end == buffer + t.text.size() && errno != ERANGE) return v;
    }
    fail(t.line, "bad number '" + std::string(t.text) + "' for coordinate " + std::to_string(coordinate) +
                     " of node '" + std::string(nodeName) + "'");
  }

  void readCoordinates(const std::vector<Token>& body, int dim) {
    if (dim > spaceDim_) spaceDim_ = dim;
    mesh_.reserve(mesh_.nodeCount() + static_cast<int>(body.size() / static_cast<std::size_t>(dim + 1)), 0, 0);
    for (std::size_t k = 0; k < body.size();) {
      const Token& name = body[k++];
      Eigen::Vector3d x = Eigen::Vector3d::Zero();
      for (int d = 0; d < dim; ++d) {
        if (k >= body.size())
          fail(name.line, "node '" + std::string(name.text) + "' needs " + std::to_string(dim) +
                              " coordinates, the section ends after " + std::to_string(d));
        x[d] = number(body[k++], name.text, d + 1);
      }
      const std::string nodeName(name.text);
      const int before = mesh_.nodeCount();
      try {
        mesh_.addNode(x, nodeName);
      } catch (const Error&) {
        if (mesh_.nodeCount() == before) fail(name.line, "duplicate node name '" + nodeName + "'");
        throw;
      }
    }
  }

  void readCells(const std::vector<Token>& body, CellType type) {
    const int n = nodeCount(type);
    for (std::size_t k = 0; k < body.size();) {
      PendingCell cell{type, body[k++], cellNodes_.size()};
      for (int j = 0; j < n; ++j) {
        if (k >= body.size())
          fail(cell.name.line, cellTypeName(type) + " cell '" + std::string(cell.name.text) + "' needs " +
                                   std::to_string(n) + " nodes, the section ends after " + std::to_string(j));
        cellNodes_.push_back(body[k++]);
      }
      cells_.push_back(cell);
    }
  }

  void readGroup(const std::vector<Token>& body, bool ofCells, const Header& header, int line) {
    PendingGroup g{ofCells, header.groupName, line, {}};
    std::size_t k = 0;
    if (g.name.empty()) {
      if (body.empty()) fail(line, std::string(ofCells ? "GROUP_MA" : "GROUP_NO") + " section without a group name");
      g.name = std::string(body[k++].text);
      if (!header.ignoredText.empty())
        alarm(line, "the text '" + header.ignoredText + "' after " + (ofCells ? "GROUP_MA" : "GROUP_NO") +
                        " is ignored, as code_aster does (it is not NOM=...): the group is named after the first "
                        "word of the section, '" + g.name + "'");
    }
    g.members.assign(body.begin() + static_cast<std::ptrdiff_t>(k), body.end());
    for (const auto& other : groups_)
      if (other.ofCells == ofCells && other.name == g.name)
        fail(line, "group '" + g.name + "' is defined twice (first at line " + std::to_string(other.line) + ")");
    groups_.push_back(std::move(g));
  }

  Mesh build() {
    mesh_.setSpaceDimension(spaceDim_ == 0 ? 3 : spaceDim_);
    mesh_.reserve(mesh_.nodeCount(), static_cast<int>(cells_.size()), static_cast<int>(cellNodes_.size()));
    int nodes[kMaxCellNodes];
    for (const auto& c : cells_) {
      const int n = nodeCount(c.type);
      for (int j = 0; j < n; ++j) {
        const Token& t = cellNodes_[c.firstNode + static_cast<std::size_t>(j)];
        nodes[j] = mesh_.findNode(std::string(t.text));
        if (nodes[j] < 0)
          fail(t.line, "node '" + std::string(t.text) + "' of cell '" + std::string(c.name.text) +
                           "' is not defined in any COOR section");
      }
      const std::string cellName(c.name.text);
      const int before = mesh_.cellCount();
      try {
        mesh_.addCell(c.type, nodes, n, cellName);
      } catch (const Error&) {
        if (mesh_.cellCount() == before) fail(c.name.line, "duplicate cell name '" + cellName + "'");
        throw;
      }
    }
    for (const auto& g : groups_) {
      std::vector<int> members;
      members.reserve(g.members.size());
      for (const auto& t : g.members) {
        const std::string name(t.text);
        const int m = g.ofCells ? mesh_.findCell(name) : mesh_.findNode(name);
        if (m < 0)
          fail(t.line, std::string(g.ofCells ? "cell '" : "node '") + name + "' of group '" + g.name +
                           "' is not defined in the mesh");
        members.push_back(m);
      }
      if (g.ofCells)
        mesh_.addCellGroup(g.name, std::move(members));
      else
        mesh_.addNodeGroup(g.name, std::move(members));
    }
    return std::move(mesh_);
  }

  std::string source_;
  std::vector<std::string>* alarms_;
  std::vector<std::string_view> lines_;  // views into the text, comments removed
  bool finished_ = false;
  Mesh mesh_;
  int spaceDim_ = 0;
  std::vector<PendingCell> cells_;
  std::vector<Token> cellNodes_;
  std::vector<PendingGroup> groups_;
};

}  // namespace

Mesh parseAsterMesh(const std::string& text, const std::string& sourceName, std::vector<std::string>* alarms) {
  return AsterParser(text, sourceName, alarms).parse();
}

std::string meshFileText(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw Error("cannot open the mesh file '" + path + "'");
  std::string text(static_cast<std::size_t>(in.tellg()), '\0');
  in.seekg(0);
  if (!in.read(text.data(), static_cast<std::streamsize>(text.size())))
    throw Error("cannot read the mesh file '" + path + "'");
  return text;
}

Mesh readAsterMesh(const std::string& path, std::vector<std::string>* alarms) {
  return parseAsterMesh(meshFileText(path), path, alarms);
}

namespace {

// code_aster reads 80 columns of a line (U3.01.00) and refuses a line with more.
constexpr std::size_t kColumns = 80;

// One entry (a node and its coordinates, a cell and its nodes), its words
// padded to `width`, continued on indented lines so that no line passes column 80.
void writeEntry(std::ostream& out, const std::vector<std::string>& words, std::size_t width) {
  std::string line;
  auto flush = [&] {
    line.erase(line.find_last_not_of(' ') + 1);
    out << line << '\n';
  };
  for (std::size_t k = 0; k < words.size(); ++k) {
    const std::size_t used = line.find_last_not_of(' ') + 1;  // 0 for an empty line
    if (k > 0 && used + 1 + words[k].size() > kColumns) {
      flush();
      line.assign(width + 1, ' ');
    }
    line += ' ';
    line += words[k];
    if (words[k].size() < width) line.append(width - words[k].size(), ' ');
  }
  flush();
}

}  // namespace

void writeAsterMesh(const Mesh& mesh, std::ostream& out) {
  out << " TITRE\n";
  std::string title = mesh.title.empty() ? std::string("MESH WRITTEN BY ASTER-LITE") : mesh.title;
  for (std::size_t begin = 0; begin <= title.size();) {
    std::size_t end = title.find('\n', begin);
    if (end == std::string::npos) end = title.size();
    const std::string line = title.substr(begin, std::min(end - begin, kColumns - 2));  // only a title
    // A line starting with FIN or FINSF would end the title (and FIN the file): a comment then.
    const std::string_view first = firstWord(line);
    out << (sameWord(first, "FIN") || sameWord(first, "FINSF") ? "%" : " ") << line << "\n";
    begin = end + 1;
  }
  out << " FINSF\n %\n";
  const int dim = mesh.spaceDimension();
  out << " COOR_" << dim << "D\n";
  std::vector<std::string> words;
  char number[32];
  for (int i = 0; i < mesh.nodeCount(); ++i) {
    words.assign(1, mesh.nodeName(i));
    const auto x = mesh.node(i);
    for (int d = 0; d < dim; ++d) {
      std::snprintf(number, sizeof number, "%22.15e", x[d]);
      words.emplace_back(number);
    }
    writeEntry(out, words, 8);
  }
  out << " FINSF\n %\n";
  for (int c = 0; c < mesh.cellCount();) {
    const CellType t = mesh.cellType(c);
    out << " " << cellTypeName(t) << "\n";
    for (; c < mesh.cellCount() && mesh.cellType(c) == t; ++c) {
      words.assign(1, mesh.cellName(c));
      for (int n : mesh.cellNodes(c)) words.push_back(mesh.nodeName(n));
      writeEntry(out, words, 8);
    }
    out << " FINSF\n %\n";
  }
  auto writeGroup = [&](const char* kw, const std::string& name, const std::vector<int>& members, bool cells) {
    out << " " << kw << " NOM=" << name << "\n";
    for (int m : members) out << " " << (cells ? mesh.cellName(m) : mesh.nodeName(m)) << "\n";
    out << " FINSF\n %\n";
  };
  for (const auto& g : mesh.nodeGroupNames()) writeGroup("GROUP_NO", g, mesh.nodeGroup(g), false);
  for (const auto& g : mesh.cellGroupNames()) writeGroup("GROUP_MA", g, mesh.cellGroup(g), true);
  out << " FIN\n";
}

void writeAsterMesh(const Mesh& mesh, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw Error("cannot write the mesh file '" + path + "'");
  writeAsterMesh(mesh, out);
}

}  // namespace aster::mesh
