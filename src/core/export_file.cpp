#include "core/export_file.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "core/error.hpp"

namespace aster {

namespace fs = std::filesystem;

namespace {

struct Word {
  std::size_t begin, end;  // [begin, end) in the line
};

std::vector<Word> splitWords(const std::string& line) {
  std::vector<Word> out;
  std::size_t i = 0;
  auto blank = [&](std::size_t k) { return std::isspace(static_cast<unsigned char>(line[k])) != 0; };
  while (i < line.size()) {
    while (i < line.size() && blank(i)) ++i;
    if (i == line.size()) break;
    const std::size_t b = i;
    while (i < line.size() && !blank(i)) ++i;
    out.push_back({b, i});
  }
  return out;
}

bool readUnit(const std::string& text, int& unit) {
  if (text.empty() || !std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c); }))
    return false;
  errno = 0;
  const long v = std::strtol(text.c_str(), nullptr, 10);
  if (errno == ERANGE || v > INT_MAX) return false;
  unit = static_cast<int>(v);
  return true;
}

fs::path sameFileKey(const fs::path& p) { return fs::absolute(p).lexically_normal(); }

}  // namespace

bool ExportEntry::isCommandFile() const {
  if (folder || !data) return false;
  if (type == "comm") return true;
  return type.size() == 4 && type.compare(0, 3, "com") == 0 && std::isdigit(static_cast<unsigned char>(type[3]));
}

std::string ExportFile::where(int line) const { return source.string() + ":" + std::to_string(line); }

fs::path ExportFile::folder() const {
  const fs::path parent = source.parent_path();
  return parent.empty() ? fs::path(".") : parent;
}

fs::path ExportFile::resolve(const ExportEntry& entry) const {
  return entry.path.is_absolute() ? entry.path : folder() / entry.path;
}

const ExportParameter* ExportFile::parameter(const std::string& name) const {
  for (const auto& p : parameters)
    if (p.name == name) return &p;
  return nullptr;
}

std::optional<double> ExportFile::timeLimit() const {
  const ExportParameter* p = parameter("time_limit");
  if (!p) return std::nullopt;
  return std::strtod(p->values.front().c_str(), nullptr);  // checked when read
}

std::vector<const ExportEntry*> ExportFile::commandFiles() const {
  std::vector<const ExportEntry*> out;
  for (const auto& e : entries)
    if (e.isCommandFile()) out.push_back(&e);
  return out;
}

ExportFile parseExportFile(const std::string& text, const fs::path& source) {
  ExportFile ex;
  ex.source = source;
  std::istringstream in(text);
  int lineNo = 0;
  std::map<int, std::size_t> readOnUnit;  // unit -> index in entries
  auto fail = [&](const std::string& what) { throw Error(ex.where(lineNo) + ": " + what); };
  for (std::string line; std::getline(in, line);) {
    ++lineNo;
    const auto spans = splitWords(line);
    std::vector<std::string> w;
    for (const auto& s : spans) w.push_back(line.substr(s.begin, s.end - s.begin));
    if (w.empty() || w[0][0] == '#') continue;
    const std::string& kind = w[0];
    if (kind == "P" || kind == "A") {
      if (w.size() < 2) fail("'" + kind + "' needs a name: " + kind + " name [value ...]");
      if (kind == "A") {
        ex.arguments.insert(ex.arguments.end(), w.begin() + 1, w.end());
        continue;
      }
      ExportParameter p{w[1], std::vector<std::string>(w.begin() + 2, w.end()), lineNo};
      if (p.name == "time_limit") {
        char* end = nullptr;
        const double v = p.values.size() == 1 ? std::strtod(p.values[0].c_str(), &end) : 0.0;
        if (p.values.size() != 1 || *end != '\0' || !(v > 0.0))
          fail("P time_limit expects one positive number of seconds");
      }
      ex.parameters.push_back(std::move(p));
      continue;
    }
    if (kind != "F" && kind != "R")
      fail("unknown line kind '" + kind + "': a line is P (parameter), A (arguments), F (file) or R (folder)");
    if (w.size() < 5) fail("'" + kind + "' expects: " + kind + " type path D|R|DR unit");
    ExportEntry e;
    e.folder = kind == "R";
    e.type = w[1];
    e.line = lineNo;
    // The path is all between the type and the flags: it may hold spaces.
    e.path = line.substr(spans[2].begin, spans[spans.size() - 3].end - spans[2].begin);
    const std::string& flags = w[w.size() - 2];
    for (char c : flags) {
      bool* flag = c == 'D' ? &e.data : c == 'R' ? &e.result : c == 'C' ? &e.compressed : nullptr;
      if (!flag || *flag) fail("flags '" + flags + "': expected D (read), R (written) or DR, with C when gzipped");
      *flag = true;
    }
    if (!e.data && !e.result) fail("flags '" + flags + "': a file is read (D), written (R) or both (DR)");
    if (!readUnit(w.back(), e.unit)) fail("unit '" + w.back() + "': expected a whole number from 0 up");
    if (e.data && !e.isCommandFile() && e.unit > 0 && !e.folder) {
      auto [it, added] = readOnUnit.emplace(e.unit, ex.entries.size());
      const ExportEntry& bound = ex.entries.size() > it->second ? ex.entries[it->second] : e;
      if (!added && sameFileKey(ex.resolve(bound)) != sameFileKey(ex.resolve(e)))
        fail("unit " + std::to_string(e.unit) + " is already bound to " + bound.path.string() + " (line " +
             std::to_string(bound.line) + ")");
    }
    for (const auto& other : ex.entries) {
      if (sameFileKey(ex.resolve(other)) != sameFileKey(ex.resolve(e))) continue;
      if ((other.data && e.result && !e.data) || (other.result && !other.data && e.data))
        fail(e.path.string() + " is read (D) and written (R) on two lines (line " + std::to_string(other.line) +
             "): the run never writes over a file it reads");
    }
    ex.entries.push_back(std::move(e));
  }
  return ex;
}

ExportFile readExportFile(const fs::path& source) {
  std::ifstream in(source, std::ios::binary);
  if (!in) throw Error("cannot read the .export file " + source.string());
  std::stringstream text;
  text << in.rdbuf();
  return parseExportFile(text.str(), source);
}

}  // namespace aster
