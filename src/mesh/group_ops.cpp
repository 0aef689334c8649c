#include "mesh/group_ops.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "core/error.hpp"

namespace aster::mesh {

std::vector<int> unionOfCellGroups(const Mesh& mesh, const std::vector<std::string>& groups) {
  std::vector<int> out;
  std::set<int> seen;
  for (const auto& g : groups)
    for (int c : mesh.cellGroup(g))
      if (seen.insert(c).second) out.push_back(c);
  return out;
}

namespace {
std::vector<int> filterFirst(const Mesh& mesh, const std::vector<std::string>& groups, bool keepIfInAll) {
  if (groups.empty()) throw Error("group operation: at least one group is needed");
  std::vector<std::set<int>> others;
  for (std::size_t k = 1; k < groups.size(); ++k) {
    const auto& g = mesh.cellGroup(groups[k]);
    others.emplace_back(g.begin(), g.end());
  }
  std::vector<int> out;
  std::set<int> seen;
  for (int c : mesh.cellGroup(groups[0])) {
    bool inAll = true, inAny = false;
    for (const auto& o : others) {
      const bool in = o.count(c) > 0;
      inAll = inAll && in;
      inAny = inAny || in;
    }
    if ((keepIfInAll ? inAll : !inAny) && seen.insert(c).second) out.push_back(c);
  }
  return out;
}
}  // namespace

std::vector<int> intersectionOfCellGroups(const Mesh& mesh, const std::vector<std::string>& groups) {
  return filterFirst(mesh, groups, true);
}

std::vector<int> differenceOfCellGroups(const Mesh& mesh, const std::vector<std::string>& groups) {
  return filterFirst(mesh, groups, false);
}

std::vector<int> nodesOfCellGroups(const Mesh& mesh, const std::vector<std::string>& groups) {
  return mesh.nodesOfCells(unionOfCellGroups(mesh, groups));
}

std::vector<int> orderedChainNodes(const Mesh& mesh, const std::vector<int>& cells, int startNode) {
  if (cells.empty()) throw Error("NOEUD_ORDO: no cell given");
  std::map<int, std::vector<int>> cellsAtEnd;  // end node -> segments
  for (int c : cells) {
    if (c < 0 || c >= mesh.cellCount()) throw Error("NOEUD_ORDO: cell index out of range");
    const CellType t = mesh.cellType(c);
    if (t != CellType::SEG2 && t != CellType::SEG3 && t != CellType::SEG4)
      throw Error("NOEUD_ORDO: cell '" + mesh.cellName(c) + "' is a " + cellTypeName(t) +
                  ", only segments can form a chain");
    cellsAtEnd[mesh.cellNodes(c)[0]].push_back(c);
    cellsAtEnd[mesh.cellNodes(c)[1]].push_back(c);
  }
  std::vector<int> ends;
  for (const auto& [node, list] : cellsAtEnd) {
    if (list.size() > 2)
      throw Error("NOEUD_ORDO: node '" + mesh.nodeName(node) + "' ends " + std::to_string(list.size()) +
                  " segments; the cells do not form one chain (branching)");
    if (list.size() == 1) ends.push_back(node);
  }
  if (ends.empty()) throw Error("NOEUD_ORDO: the segments form a closed loop, not an open chain");
  if (ends.size() != 2)
    throw Error("NOEUD_ORDO: the segments form " + std::to_string(ends.size() / 2) +
                " separate chains, not one");
  int start = startNode;
  if (start >= 0) {
    if (start != ends[0] && start != ends[1])
      throw Error("NOEUD_ORDO: node '" + mesh.nodeName(start) + "' is not an end of the chain");
  } else {
    // Walk backwards from the first cell until an end: the chain starts there.
    int c = cells[0], node = mesh.cellNodes(c)[0];
    for (std::size_t step = 0; step <= cells.size(); ++step) {
      const auto& list = cellsAtEnd[node];
      if (list.size() == 1) break;
      c = list[0] == c ? list[1] : list[0];
      node = mesh.cellNodes(c)[0] == node ? mesh.cellNodes(c)[1] : mesh.cellNodes(c)[0];
    }
    start = node;
  }
  std::vector<int> out{start};
  int node = start, previous = -1;
  std::size_t visited = 0;
  while (true) {
    const auto& list = cellsAtEnd[node];
    int next = -1;
    for (int c : list)
      if (c != previous) next = c;
    if (next < 0) break;
    const auto n = mesh.cellNodes(next);
    const bool forward = n[0] == node;
    // Inner nodes in geometric order: SEG3 has one; SEG4's lie from the first end.
    if (n.size() == 3) out.push_back(n[2]);
    if (n.size() == 4) {
      out.push_back(forward ? n[2] : n[3]);
      out.push_back(forward ? n[3] : n[2]);
    }
    node = forward ? n[1] : n[0];
    out.push_back(node);
    previous = next;
    ++visited;
    if (cellsAtEnd[node].size() == 1) break;
  }
  if (visited != cells.size())
    throw Error("NOEUD_ORDO: only " + std::to_string(visited) + " of the " + std::to_string(cells.size()) +
                " segments are connected; the cells do not form one chain");
  return out;
}

std::vector<std::vector<int>> groupsOfEachCell(const Mesh& mesh) {
  const auto names = mesh.cellGroupNames();
  std::vector<std::vector<int>> groups(mesh.cellCount());
  for (std::size_t g = 0; g < names.size(); ++g)
    for (int c : mesh.cellGroup(names[g]))
      if (groups[c].empty() || groups[c].back() != static_cast<int>(g)) groups[c].push_back(static_cast<int>(g));
  return groups;
}

}  // namespace aster::mesh
