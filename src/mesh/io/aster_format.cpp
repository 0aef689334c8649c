#include "mesh/io/aster_format.hpp"

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <unordered_set>
#include <vector>

#include "core/error.hpp"
#include "core/suggest.hpp"
#include "mesh/io/words.hpp"

namespace aster::mesh {

namespace {

struct Token {
  std::string text;
  int line;
};

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

struct PendingCell {
  CellType type;
  Token name;
  std::vector<Token> nodes;
};

struct PendingGroup {
  bool ofCells;
  std::string name;
  int line;
  std::vector<Token> members;
};

class AsterParser {
 public:
  AsterParser(const std::string& text, std::string source) : source_(std::move(source)) {
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
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
      if (pct != std::string::npos) line.erase(pct);
      if (!line.empty() && line.back() == '\r') line.pop_back();
      lines_.push_back(line);
    }
  }

  Mesh parse() {
    bool finished = false;
    std::size_t i = 0;
    while (i < lines_.size()) {
      const auto words = splitWords(lines_[i]);
      if (words.empty()) {
        ++i;
        continue;
      }
      const int headerLine = static_cast<int>(i) + 1;
      const std::string keyword = upper(words[0]);
      if (keyword == "FIN") {
        finished = true;
        break;
      }
      checkKeyword(keyword, headerLine);
      const std::string groupName = headerOptions(words, headerLine);
      ++i;
      if (keyword == "TITRE") {
        std::string title;
        while (true) {
          if (i >= lines_.size()) truncated("TITRE", headerLine);
          const auto w = splitWords(lines_[i]);
          ++i;
          if (!w.empty() && upper(w[0]) == "FINSF") break;
          std::string trimmed = lines_[i - 1];
          trimmed.erase(0, trimmed.find_first_not_of(" \t"));
          trimmed.erase(trimmed.find_last_not_of(" \t") + 1);
          if (!trimmed.empty()) title += (title.empty() ? "" : "\n") + trimmed;
        }
        mesh_.title = title;
        continue;
      }
      const auto body = sectionTokens(i, keyword, headerLine);
      if (keyword.rfind("COOR_", 0) == 0)
        readCoordinates(body, keyword[5] - '0');
      else if (keyword == "GROUP_MA" || keyword == "GROUP_NO")
        readGroup(body, keyword == "GROUP_MA", groupName, headerLine);
      else
        readCells(body, cellTypeFromName(keyword));
    }
    if (!finished && lines_.empty()) throw Error(source_ + ": the file is empty (expected an ASTER mesh ended by FIN)");
    if (!finished)
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

  // Options on the header line: NOM=... (groups), INFO=... (ignored).
  std::string headerOptions(const std::vector<std::string>& words, int line) const {
    std::string name;
    // Split "KEY=VALUE", "KEY = VALUE", "KEY= VALUE" alike.
    std::string compact;
    for (std::size_t k = 1; k < words.size(); ++k) compact += words[k];
    std::size_t pos = 0;
    while (pos < compact.size()) {
      const auto eq = compact.find('=', pos);
      if (eq == std::string::npos) fail(line, "unexpected text '" + compact.substr(pos) + "' after the section keyword (expected KEY=VALUE)");
      const std::string key = upper(compact.substr(pos, eq - pos));
      // The value runs until the next known key or the end.
      std::size_t end = compact.size();
      for (const char* next : {"NOM=", "INFO="}) {
        const auto n = upper(compact).find(next, eq + 1);
        if (n != std::string::npos && n < end) end = n;
      }
      std::string value = compact.substr(eq + 1, end - eq - 1);
      if (value.size() >= 2 && (value.front() == '\'' || value.front() == '"')) value = value.substr(1, value.size() - 2);
      if (key == "NOM") {
        if (value.empty()) fail(line, "NOM= needs a group name");
        name = value;
      } else if (key != "INFO") {
        fail(line, "unknown option '" + key + "' on a section line (expected NOM= or INFO=)");
      }
      pos = end;
    }
    const std::string keyword = upper(words[0]);
    if (!name.empty() && keyword != "GROUP_MA" && keyword != "GROUP_NO")
      fail(line, "NOM= is only allowed on GROUP_MA and GROUP_NO lines");
    return name;
  }

  std::vector<Token> sectionTokens(std::size_t& i, const std::string& section, int headerLine) const {
    std::vector<Token> tokens;
    while (true) {
      if (i >= lines_.size()) truncated(section, headerLine);
      const int lineNo = static_cast<int>(i) + 1;
      const auto words = splitWords(lines_[i]);
      ++i;
      for (std::size_t k = 0; k < words.size(); ++k) {
        if (upper(words[k]) == "FINSF") {
          if (k + 1 < words.size()) fail(lineNo, "unexpected text '" + words[k + 1] + "' after FINSF");
          return tokens;
        }
        if (upper(words[k]) == "FIN" && k == 0 && words.size() == 1)
          fail(lineNo, "FIN found inside section " + section + " opened at line " +
                           std::to_string(headerLine) + " (expected FINSF first)");
        tokens.push_back({words[k], lineNo});
      }
    }
  }

  double number(const Token& t, const std::string& what) const {
    std::string s = t.text;
    for (char& c : s)
      if (c == 'D' || c == 'd') c = 'E';
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || end != s.c_str() + s.size() || errno == ERANGE)
      fail(t.line, "bad number '" + t.text + "' for " + what);
    return v;
  }

  void readCoordinates(const std::vector<Token>& body, int dim) {
    if (dim > spaceDim_) spaceDim_ = dim;
    for (std::size_t k = 0; k < body.size();) {
      const Token& name = body[k++];
      Eigen::Vector3d x = Eigen::Vector3d::Zero();
      for (int d = 0; d < dim; ++d) {
        if (k >= body.size())
          fail(name.line, "node '" + name.text + "' needs " + std::to_string(dim) +
                              " coordinates, the section ends after " + std::to_string(d));
        x[d] = number(body[k++], "coordinate " + std::to_string(d + 1) + " of node '" + name.text + "'");
      }
      if (mesh_.findNode(name.text) >= 0) fail(name.line, "duplicate node name '" + name.text + "'");
      mesh_.addNode(x, name.text);
    }
  }

  void readCells(const std::vector<Token>& body, CellType type) {
    const int n = nodeCount(type);
    for (std::size_t k = 0; k < body.size();) {
      PendingCell cell{type, body[k++], {}};
      for (int j = 0; j < n; ++j) {
        if (k >= body.size())
          fail(cell.name.line, cellTypeName(type) + " cell '" + cell.name.text + "' needs " +
                                   std::to_string(n) + " nodes, the section ends after " + std::to_string(j));
        cell.nodes.push_back(body[k++]);
      }
      if (!cellNames_.insert(cell.name.text).second)
        fail(cell.name.line, "duplicate cell name '" + cell.name.text + "'");
      cells_.push_back(std::move(cell));
    }
  }

  void readGroup(const std::vector<Token>& body, bool ofCells, const std::string& headerName, int line) {
    PendingGroup g{ofCells, headerName, line, {}};
    std::size_t k = 0;
    if (g.name.empty()) {
      if (body.empty()) fail(line, std::string(ofCells ? "GROUP_MA" : "GROUP_NO") + " section without a group name");
      g.name = body[k++].text;
    }
    g.members.assign(body.begin() + static_cast<std::ptrdiff_t>(k), body.end());
    for (const auto& other : groups_)
      if (other.ofCells == ofCells && other.name == g.name)
        fail(line, "group '" + g.name + "' is defined twice (first at line " + std::to_string(other.line) + ")");
    groups_.push_back(std::move(g));
  }

  Mesh build() {
    mesh_.setSpaceDimension(spaceDim_ == 0 ? 3 : spaceDim_);
    std::vector<int> nodes;
    for (const auto& c : cells_) {
      nodes.clear();
      for (const auto& t : c.nodes) {
        const int n = mesh_.findNode(t.text);
        if (n < 0) fail(t.line, "node '" + t.text + "' of cell '" + c.name.text + "' is not defined in any COOR section");
        nodes.push_back(n);
      }
      mesh_.addCell(c.type, nodes, c.name.text);
    }
    for (const auto& g : groups_) {
      std::vector<int> members;
      for (const auto& t : g.members) {
        const int m = g.ofCells ? mesh_.findCell(t.text) : mesh_.findNode(t.text);
        if (m < 0)
          fail(t.line, std::string(g.ofCells ? "cell '" : "node '") + t.text + "' of group '" + g.name +
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
  std::vector<std::string> lines_;
  Mesh mesh_;
  int spaceDim_ = 0;
  std::vector<PendingCell> cells_;
  std::unordered_set<std::string> cellNames_;
  std::vector<PendingGroup> groups_;
};

}  // namespace

Mesh parseAsterMesh(const std::string& text, const std::string& sourceName) {
  return AsterParser(text, sourceName).parse();
}

Mesh readAsterMesh(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot open the mesh file '" + path + "'");
  std::ostringstream text;
  text << in.rdbuf();
  return parseAsterMesh(text.str(), path);
}

void writeAsterMesh(const Mesh& mesh, std::ostream& out) {
  out << " TITRE\n " << (mesh.title.empty() ? std::string("MESH WRITTEN BY ASTER-LITE") : mesh.title)
      << "\n FINSF\n %\n";
  const int dim = mesh.spaceDimension();
  out << " COOR_" << dim << "D\n";
  out << std::scientific << std::setprecision(15);
  for (int i = 0; i < mesh.nodeCount(); ++i) {
    out << " " << std::left << std::setw(8) << mesh.nodeName(i) << std::right;
    const auto x = mesh.node(i);
    for (int d = 0; d < dim; ++d) out << " " << std::setw(22) << x[d];
    out << "\n";
  }
  out << " FINSF\n %\n";
  for (int c = 0; c < mesh.cellCount();) {
    const CellType t = mesh.cellType(c);
    out << " " << cellTypeName(t) << "\n";
    for (; c < mesh.cellCount() && mesh.cellType(c) == t; ++c) {
      out << " " << std::left << std::setw(8) << mesh.cellName(c);
      int k = 0;
      for (int n : mesh.cellNodes(c)) {
        if (k > 0 && k % 8 == 0) out << "\n " << std::setw(8) << "";
        out << " " << std::setw(8) << mesh.nodeName(n);
        ++k;
      }
      out << std::right << "\n";
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
