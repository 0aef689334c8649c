#include "commands/selection.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "core/suggest.hpp"

namespace aster::lang {
namespace {

void appendUnique(std::vector<int>& out, std::vector<char>& seen, const std::vector<int>& items) {
  for (int i : items)
    if (!seen[i]) {
      seen[i] = 1;
      out.push_back(i);
    }
}

// A group named in a command must hold something: an empty one would make the
// occurrence apply to nothing, silently.
const std::vector<int>& nonEmpty(const std::vector<int>& members, const std::string& group, const char* what,
                                 const Keywords& occ) {
  if (members.empty())
    throw Error((occ.path.empty() ? std::string() : occ.path + ": ") + "group '" + group + "' is empty (no " +
                what + "): the keyword would apply to nothing");
  return members;
}

[[noreturn]] void unknownName(const Keywords& occ, const std::string& key, const char* what, const std::string& name,
                              const std::vector<std::string>& names) {
  throw Error((occ.path.empty() ? key : occ.path + "/" + key) + ": " + what + " '" + name +
              "' not found in the mesh;" + didYouMean(name, names, true));
}

std::vector<int> cellsOfKeywords(const mesh::Mesh& mesh, const Keywords& occ, const char* groupKey,
                                 const char* nameKey) {
  std::vector<int> out;
  std::vector<char> seen(mesh.cellCount(), 0);
  for (const auto& g : occ.texts(groupKey)) appendUnique(out, seen, nonEmpty(mesh.cellGroup(g), g, "cell", occ));
  appendUnique(out, seen, namedCells(mesh, occ, nameKey));
  return out;
}

std::vector<int> without(std::vector<int> items, const std::vector<int>& excluded, std::size_t size) {
  if (excluded.empty()) return items;
  std::vector<char> drop(size, 0);
  for (int i : excluded) drop[i] = 1;
  items.erase(std::remove_if(items.begin(), items.end(), [&](int i) { return drop[i] != 0; }), items.end());
  return items;
}

}  // namespace

int namedNode(const mesh::Mesh& mesh, const Keywords& occ, const std::string& key, const std::string& name) {
  const int n = mesh.findNode(name);
  if (n >= 0) return n;
  std::vector<std::string> names;
  names.reserve(mesh.nodeCount());
  for (int i = 0; i < mesh.nodeCount(); ++i) names.push_back(mesh.nodeName(i));
  unknownName(occ, key, "node", name, names);
}

int namedCell(const mesh::Mesh& mesh, const Keywords& occ, const std::string& key, const std::string& name) {
  const int c = mesh.findCell(name);
  if (c >= 0) return c;
  std::vector<std::string> names;
  names.reserve(mesh.cellCount());
  for (int i = 0; i < mesh.cellCount(); ++i) names.push_back(mesh.cellName(i));
  unknownName(occ, key, "cell", name, names);
}

std::vector<int> namedNodes(const mesh::Mesh& mesh, const Keywords& occ, const std::string& key) {
  std::vector<int> out;
  if (!occ.has(key)) return out;
  for (const auto& name : occ.texts(key)) out.push_back(namedNode(mesh, occ, key, name));
  return out;
}

std::vector<int> namedCells(const mesh::Mesh& mesh, const Keywords& occ, const std::string& key) {
  std::vector<int> out;
  if (!occ.has(key)) return out;
  for (const auto& name : occ.texts(key)) out.push_back(namedCell(mesh, occ, key, name));
  return out;
}

std::vector<int> selectCells(const mesh::Mesh& mesh, const Keywords& occ) {
  std::vector<int> out;
  std::vector<char> seen(mesh.cellCount(), 0);
  if (occ.has("TOUT")) {
    std::vector<int> all(mesh.cellCount());
    for (int c = 0; c < mesh.cellCount(); ++c) all[c] = c;
    appendUnique(out, seen, all);
  }
  appendUnique(out, seen, cellsOfKeywords(mesh, occ, "GROUP_MA", "MAILLE"));
  return without(std::move(out), cellsOfKeywords(mesh, occ, "SANS_GROUP_MA", "SANS_MAILLE"), mesh.cellCount());
}

std::vector<int> selectNodes(const mesh::Mesh& mesh, const Keywords& occ) {
  std::vector<int> out;
  std::vector<char> seen(mesh.nodeCount(), 0);
  std::vector<int> cells;
  if (occ.has("TOUT")) {
    cells.resize(mesh.cellCount());
    for (int c = 0; c < mesh.cellCount(); ++c) cells[c] = c;
  }
  for (int c : cellsOfKeywords(mesh, occ, "GROUP_MA", "MAILLE")) cells.push_back(c);
  appendUnique(out, seen, mesh.nodesOfCells(cells));
  for (const auto& g : occ.texts("GROUP_NO")) appendUnique(out, seen, nonEmpty(mesh.nodeGroup(g), g, "node", occ));
  appendUnique(out, seen, namedNodes(mesh, occ, "NOEUD"));
  return without(std::move(out), excludedNodes(mesh, occ), mesh.nodeCount());
}

std::vector<int> excludedNodes(const mesh::Mesh& mesh, const Keywords& occ) {
  std::vector<int> out = mesh.nodesOfCells(cellsOfKeywords(mesh, occ, "SANS_GROUP_MA", "SANS_MAILLE"));
  for (const auto& g : occ.texts("SANS_GROUP_NO")) {
    const auto& members = nonEmpty(mesh.nodeGroup(g), g, "node", occ);
    out.insert(out.end(), members.begin(), members.end());
  }
  for (int n : namedNodes(mesh, occ, "SANS_NOEUD")) out.push_back(n);
  return out;
}

}  // namespace aster::lang
