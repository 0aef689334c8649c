#include "mesh/cell_children.hpp"

#include <string>
#include <unordered_set>

namespace aster::mesh {

std::vector<std::vector<int>> addCellsAndChildren(const Mesh& in, const std::vector<CellChildren>& children,
                                                  Mesh& out) {
  std::unordered_set<std::string> taken;
  for (int c = 0; c < in.cellCount(); ++c)
    if (children[c].empty()) taken.insert(in.cellName(c));
  int counter = 1;
  auto freshName = [&] {
    std::string name;
    do name = "M" + std::to_string(counter++);
    while (taken.count(name));
    taken.insert(name);
    return name;
  };
  std::vector<std::vector<int>> newCells(in.cellCount());
  for (int c = 0; c < in.cellCount(); ++c) {
    if (children[c].empty()) {
      const auto n = in.cellNodes(c);
      newCells[c].push_back(out.addCell(in.cellType(c), n.first, n.count, in.cellName(c)));
    } else {
      for (const auto& [type, nodes] : children[c]) newCells[c].push_back(out.addCell(type, nodes, freshName()));
    }
  }
  for (const auto& g : in.cellGroupNames()) {
    std::vector<int> members;
    for (int c : in.cellGroup(g)) members.insert(members.end(), newCells[c].begin(), newCells[c].end());
    out.addCellGroup(g, std::move(members));
  }
  return newCells;
}

}  // namespace aster::mesh
