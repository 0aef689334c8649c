// Numbering of the unknowns: each node owns a contiguous run of DOFs
// (first(node) .. first(node)+count(node)-1). Displacement components come
// first (DX, DY), extra per-node unknowns (e.g. a contact pressure on slave
// nodes) after them. Nodes are numbered in their given order; fill-reducing
// ordering is left to the sparse solver (CHOLMOD/UMFPACK do AMD/METIS).
#pragma once
#include <vector>

namespace aster::fem {

class DofMap {
 public:
  DofMap() = default;
  DofMap(int nodeCount, int dofsPerNode);
  explicit DofMap(const std::vector<int>& dofsPerNode);

  // Same map with `extra` more DOFs on each listed node (after its existing ones).
  DofMap withExtraDofs(const std::vector<int>& nodes, int extra) const;

  int nodeCount() const { return static_cast<int>(first_.size()) - 1; }
  int dofCount() const { return first_.back(); }
  int first(int node) const { return first_[node]; }
  int count(int node) const { return first_[node + 1] - first_[node]; }
  // Unchecked: for element loops.
  int dof(int node, int component) const { return first_[node] + component; }
  // Checked: throws aster::Error when the node or the component does not exist.
  int at(int node, int component) const;

  // The DOF list of a cell (or of any nodes [first, last)): components
  // 0..components-1 of each node, node-major, the order the element kernels use
  // (DX, DY of node 0, then of node 1...), appended to `out`. A node that
  // carries no DOF gives -1, "not assembled", for each component.
  void appendNodeDofs(const int* first, const int* last, int components, std::vector<int>& out) const;

 private:
  std::vector<int> first_{0};  // size nodeCount + 1, prefix sums of counts
};

}  // namespace aster::fem
