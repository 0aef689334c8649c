// The global DOFs of each element, stored flat (CSR-like). An element's local
// DOF order is the order given here; for cells built from a connectivity it is
// node-major: (node0 c0, node0 c1, node1 c0, ...), the order the element
// kernels use. A negative DOF means "not assembled" (e.g. eliminated).
#pragma once
#include <vector>

#include "fem/dof_map.hpp"

namespace aster::fem {

class ElementDofs {
 public:
  // Appends one element; returns its index.
  int add(const int* dofs, int count);
  int add(const std::vector<int>& dofs) { return add(dofs.data(), static_cast<int>(dofs.size())); }
  // Appends one element per cell: components 0..components-1 of each node.
  // Returns the index of the first element appended.
  int addCells(const std::vector<std::vector<int>>& cells, const DofMap& map, int components);

  int elementCount() const { return static_cast<int>(offsets_.size()) - 1; }
  int size(int e) const { return offsets_[e + 1] - offsets_[e]; }
  const int* dofs(int e) const { return dofs_.data() + offsets_[e]; }
  int largestDof() const { return largest_; }

 private:
  std::vector<int> offsets_{0};
  std::vector<int> dofs_;
  int largest_ = -1;
};

}  // namespace aster::fem
