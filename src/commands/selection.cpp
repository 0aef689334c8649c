#include "commands/selection.hpp"

#include <algorithm>

#include "core/error.hpp"

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

}  // namespace

std::vector<int> selectCells(const mesh::Mesh& mesh, const Keywords& occ) {
  std::vector<int> out;
  std::vector<char> seen(mesh.cellCount(), 0);
  if (occ.has("TOUT")) {
    std::vector<int> all(mesh.cellCount());
    for (int c = 0; c < mesh.cellCount(); ++c) all[c] = c;
    appendUnique(out, seen, all);
  }
  for (const auto& g : occ.texts("GROUP_MA")) appendUnique(out, seen, nonEmpty(mesh.cellGroup(g), g, "cell", occ));
  for (const auto& name : occ.texts("MAILLE")) appendUnique(out, seen, {mesh.cellIndex(name)});
  return out;
}

std::vector<int> selectNodes(const mesh::Mesh& mesh, const Keywords& occ) {
  std::vector<int> out;
  std::vector<char> seen(mesh.nodeCount(), 0);
  const auto cells = selectCells(mesh, occ);
  appendUnique(out, seen, mesh.nodesOfCells(cells));
  for (const auto& g : occ.texts("GROUP_NO")) appendUnique(out, seen, nonEmpty(mesh.nodeGroup(g), g, "node", occ));
  for (const auto& name : occ.texts("NOEUD")) appendUnique(out, seen, {mesh.nodeIndex(name)});
  return out;
}

}  // namespace aster::lang
