#include "fem/assembly_pattern.hpp"

#include <algorithm>
#include <string>

#include "core/error.hpp"
#include "core/parallel_fill.hpp"

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
  // Every position -1 first, filled on the pool's threads (the first touch of a large
  // block): the entries of negative DOFs keep it, the others are written below.
  positions_.reset(new int[static_cast<std::size_t>(positionOffsets_[ne])]);
  parallelFill(positions_.get(), static_cast<std::size_t>(positionOffsets_[ne]), -1);

  // Two passes over the columns: the number of distinct rows of each (marker array), then,
  // in the matrix allocated at its final size, the sorted rows, to which each touching
  // element's column entries point.
  std::vector<int> mark(dofCount, -1);
  auto distinctRows = [&](int j, auto&& onRow) {
    for (int t = start[j]; t < start[j + 1]; ++t) {
      const int* d = elements.dofs(touchElement[t]);
      for (int i = 0; i < elements.size(touchElement[t]); ++i)
        if (d[i] >= 0 && mark[d[i]] != j) {
          mark[d[i]] = j;
          onRow(d[i]);
        }
    }
  };
  std::vector<std::int64_t> count(dofCount + 1, 0);
  for (int j = 0; j < dofCount; ++j) distinctRows(j, [&](int) { ++count[j + 1]; });
  for (int j = 0; j < dofCount; ++j) count[j + 1] += count[j];
  if (count[dofCount] > 2147483647LL) throw Error("AssemblyPattern: more than 2^31 non-zeros");
  nonZeros_ = count[dofCount];
  pattern_.resize(dofCount, dofCount);
  pattern_.resizeNonZeros(static_cast<Eigen::Index>(nonZeros_));
  int* outer = pattern_.outerIndexPtr();
  int* inner = pattern_.innerIndexPtr();
  parallelFill(inner, static_cast<std::size_t>(nonZeros_), 0);  // touched on every thread, written below
  for (int j = 0; j <= dofCount; ++j) outer[j] = static_cast<int>(count[j]);
  std::fill(mark.begin(), mark.end(), -1);
  std::vector<int> positionOfRow(dofCount, -1);
  for (int j = 0; j < dofCount; ++j) {
    int* rows = inner + outer[j];
    int k = 0;
    distinctRows(j, [&](int row) { rows[k++] = row; });
    std::sort(rows, rows + k);
    for (int r = 0; r < k; ++r) positionOfRow[rows[r]] = outer[j] + r;
    for (int t = start[j]; t < start[j + 1]; ++t) {
      const int e = touchElement[t], lj = touchLocal[t], n = elements.size(e);
      const int* d = elements.dofs(e);
      int* pos = positions_.get() + positionOffsets_[e] + static_cast<std::int64_t>(lj) * n;
      for (int i = 0; i < n; ++i) pos[i] = d[i] >= 0 ? positionOfRow[d[i]] : -1;
    }
  }
  // Columns of negative DOFs are never reached: their entries keep -1, unassembled.
  parallelFill(pattern_.valuePtr(), static_cast<std::size_t>(nonZeros_), 0.0);
}

linalg::SparseMatrix AssemblyPattern::newMatrix() const {
  if (taken_) throw Error("AssemblyPattern: newMatrix() after takeMatrix()");
  return pattern_;
}

void AssemblyPattern::takeMatrix(linalg::SparseMatrix& A) {
  if (taken_) throw Error("AssemblyPattern: takeMatrix() called twice");
  taken_ = true;
  A.swap(pattern_);
  pattern_ = linalg::SparseMatrix();
}

void AssemblyPattern::checkSize(int e, int rows, int cols, const linalg::SparseMatrix& A) const {
  if (e < 0 || e >= elements_.elementCount())
    throw Error("AssemblyPattern: element " + std::to_string(e) + " out of range");
  const int n = elements_.size(e);
  if (rows != n || cols != n)
    throw Error("AssemblyPattern: element " + std::to_string(e) + " has " + std::to_string(n) +
                " DOFs but its matrix is " + std::to_string(rows) + "x" + std::to_string(cols));
  if (A.rows() != dofCount_ || A.nonZeros() != nonZeros_ || !A.isCompressed())
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
