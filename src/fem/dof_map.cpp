#include "fem/dof_map.hpp"

#include <string>

#include "core/error.hpp"

namespace aster::fem {

DofMap::DofMap(int nodeCount, int dofsPerNode) : DofMap(std::vector<int>(nodeCount < 0 ? 0 : nodeCount, dofsPerNode)) {
  if (nodeCount < 0) throw Error("DofMap: negative node count " + std::to_string(nodeCount));
}

DofMap::DofMap(const std::vector<int>& dofsPerNode) {
  first_.assign(dofsPerNode.size() + 1, 0);
  long long total = 0;
  for (std::size_t n = 0; n < dofsPerNode.size(); ++n) {
    if (dofsPerNode[n] < 0)
      throw Error("DofMap: negative DOF count " + std::to_string(dofsPerNode[n]) + " at node " + std::to_string(n));
    total += dofsPerNode[n];
    if (total > 2000000000LL) throw Error("DofMap: more than 2e9 DOFs");
    first_[n + 1] = static_cast<int>(total);
  }
}

DofMap DofMap::withExtraDofs(const std::vector<int>& nodes, int extra) const {
  std::vector<int> counts(nodeCount());
  for (int n = 0; n < nodeCount(); ++n) counts[n] = count(n);
  for (int n : nodes) {
    if (n < 0 || n >= nodeCount())
      throw Error("DofMap: node " + std::to_string(n) + " out of range 0.." + std::to_string(nodeCount() - 1));
    counts[n] += extra;
  }
  return DofMap(counts);
}

int DofMap::at(int node, int component) const {
  if (node < 0 || node >= nodeCount())
    throw Error("DofMap: node " + std::to_string(node) + " out of range 0.." + std::to_string(nodeCount() - 1));
  if (component < 0 || component >= count(node))
    throw Error("DofMap: node " + std::to_string(node) + " has " + std::to_string(count(node)) +
                " DOFs, component " + std::to_string(component) + " requested");
  return first_[node] + component;
}

void DofMap::appendNodeDofs(const int* first, const int* last, int components, std::vector<int>& out) const {
  for (const int* node = first; node != last; ++node)
    for (int k = 0; k < components; ++k) out.push_back(count(*node) ? dof(*node, k) : -1);
}

}  // namespace aster::fem
