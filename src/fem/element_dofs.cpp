#include "fem/element_dofs.hpp"

#include <string>

#include "core/error.hpp"

namespace aster::fem {

int ElementDofs::add(const int* dofs, int count) {
  if (count < 0) throw Error("ElementDofs: negative DOF count");
  dofs_.insert(dofs_.end(), dofs, dofs + count);
  for (int i = 0; i < count; ++i)
    if (dofs[i] > largest_) largest_ = dofs[i];
  offsets_.push_back(static_cast<int>(dofs_.size()));
  return elementCount() - 1;
}

int ElementDofs::addCells(const std::vector<std::vector<int>>& cells, const DofMap& map, int components) {
  const int firstElement = elementCount();
  std::vector<int> local;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    local.clear();
    for (int node : cells[c]) {
      if (node < 0 || node >= map.nodeCount())
        throw Error("ElementDofs: cell " + std::to_string(c) + " refers to node " + std::to_string(node) +
                    " out of range 0.." + std::to_string(map.nodeCount() - 1));
      if (map.count(node) < components)
        throw Error("ElementDofs: node " + std::to_string(node) + " has " + std::to_string(map.count(node)) +
                    " DOFs, cell " + std::to_string(c) + " needs " + std::to_string(components));
    }
    map.appendNodeDofs(cells[c].data(), cells[c].data() + cells[c].size(), components, local);
    add(local);
  }
  return firstElement;
}

}  // namespace aster::fem
