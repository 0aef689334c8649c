#include "fem/assembly_pattern.hpp"

#include <algorithm>
#include <string>

#include "core/error.hpp"

namespace aster::fem {

AssemblyPattern::AssemblyPattern(int dofCount, const ElementDofs& elements)
    : dofCount_(dofCount), elements_(elements) {
  if (dofCount < 0) throw Error("AssemblyPattern: negative DOF count");
  if (elements.largestDof() >= dofCount)
    throw Error("AssemblyPattern: an element refers to DOF " + std::to_string(elements.largestDof()) + " but only " +
                std::to_string(dofCount) + " DOFs exist");
  const int ne = elements.elementCount();

  // Transpose: for each DOF, the (element, local index) pairs that touch it.
  std::vector<int> start(dofCount + 1, 0);
  for (int e = 0; e < ne; ++e)
    for (int i = 0; i < elements.size(e); ++i)
      if (elements.dofs(e)[i] >= 0) ++start[elements.dofs(e)[i] + 1];
  for (int d = 0; d < dofCount; ++d) start[d + 1] += start[d];
  std::vector<int> touchElement(start[dofCount]), touchLocal(start[dofCount]);
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int e = 0; e < ne; ++e)
      for (int i = 0; i < elements.size(e); ++i) {
        const int d = elements.dofs(e)[i];
        if (d < 0) continue;
        touchElement[fill[d]] = e;
        touchLocal[fill[d]] = i;
        ++fill[d];
      }
  }

  positionOffsets_.resize(ne + 1, 0);
  for (int e = 0; e < ne; ++e)
    positionOffsets_[e + 1] = positionOffsets_[e] + static_cast<std::int64_t>(elements.size(e)) * elements.size(e);
  positions_.assign(positionOffsets_[ne], -1);

  // Column by column: the distinct rows (marker array), sorted, then each
  // touching element's column entries point at their row's position.
  std::vector<int> outer(dofCount + 1, 0);
  std::vector<int> inner;
  inner.reserve(static_cast<std::size_t>(start[dofCount]) * 4);
  std::vector<int> mark(dofCount, -1), positionOfRow(dofCount, -1);
  std::vector<int> rows;
  for (int j = 0; j < dofCount; ++j) {
    rows.clear();
    for (int t = start[j]; t < start[j + 1]; ++t) {
      const int e = touchElement[t];
      const int* d = elements.dofs(e);
      for (int i = 0; i < elements.size(e); ++i)
        if (d[i] >= 0 && mark[d[i]] != j) {
          mark[d[i]] = j;
          rows.push_back(d[i]);
        }
    }
    std::sort(rows.begin(), rows.end());
    const std::int64_t base = static_cast<std::int64_t>(inner.size());
    if (base + static_cast<std::int64_t>(rows.size()) > 2147483647LL)
      throw Error("AssemblyPattern: more than 2^31 non-zeros");
    for (std::size_t k = 0; k < rows.size(); ++k) {
      positionOfRow[rows[k]] = static_cast<int>(base + static_cast<std::int64_t>(k));
      inner.push_back(rows[k]);
    }
    outer[j + 1] = static_cast<int>(inner.size());
    for (int t = start[j]; t < start[j + 1]; ++t) {
      const int e = touchElement[t], lj = touchLocal[t], n = elements.size(e);
      const int* d = elements.dofs(e);
      int* pos = positions_.data() + positionOffsets_[e] + static_cast<std::int64_t>(lj) * n;
      for (int i = 0; i < n; ++i) pos[i] = d[i] >= 0 ? positionOfRow[d[i]] : -1;
    }
  }

  pattern_.resize(dofCount, dofCount);
  pattern_.resizeNonZeros(static_cast<Eigen::Index>(inner.size()));
  std::copy(outer.begin(), outer.end(), pattern_.outerIndexPtr());
  std::copy(inner.begin(), inner.end(), pattern_.innerIndexPtr());
  std::fill(pattern_.valuePtr(), pattern_.valuePtr() + inner.size(), 0.0);
}

void AssemblyPattern::checkSize(int e, int rows, int cols, const SparseMatrix& A) const {
  if (e < 0 || e >= elements_.elementCount())
    throw Error("AssemblyPattern: element " + std::to_string(e) + " out of range");
  const int n = elements_.size(e);
  if (rows != n || cols != n)
    throw Error("AssemblyPattern: element " + std::to_string(e) + " has " + std::to_string(n) +
                " DOFs but its matrix is " + std::to_string(rows) + "x" + std::to_string(cols));
  if (A.rows() != dofCount_ || A.nonZeros() != pattern_.nonZeros() || !A.isCompressed())
    throw Error("AssemblyPattern: the target matrix was not created by this pattern's newMatrix()");
}

std::vector<std::vector<int>> colourElements(const ElementDofs& elements, int dofCount) {
  // A 64-bit mask per DOF of the colours already used around it.
  std::vector<std::uint64_t> used(dofCount, 0);
  std::vector<std::vector<int>> colours;
  for (int e = 0; e < elements.elementCount(); ++e) {
    const int* d = elements.dofs(e);
    std::uint64_t taken = 0;
    for (int i = 0; i < elements.size(e); ++i)
      if (d[i] >= 0) {
        if (d[i] >= dofCount) throw Error("colourElements: DOF " + std::to_string(d[i]) + " out of range");
        taken |= used[d[i]];
      }
    if (taken == ~std::uint64_t(0)) throw Error("colourElements: more than 64 colours needed");
    int c = 0;
    while (taken & (std::uint64_t(1) << c)) ++c;
    for (int i = 0; i < elements.size(e); ++i)
      if (d[i] >= 0) used[d[i]] |= std::uint64_t(1) << c;
    if (c >= static_cast<int>(colours.size())) colours.resize(c + 1);
    colours[c].push_back(e);
  }
  return colours;
}

}  // namespace aster::fem
