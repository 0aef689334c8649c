// Sparsity pattern of a finite element matrix, built once from the elements'
// DOFs, with each element's entries mapped to their positions in the CSC value
// array: re-assembly only adds into values (no search, no allocation).
// The matrix is square, column-major (Eigen's default CSC), with sorted rows;
// entries coupling negative (non-assembled) DOFs are skipped. No reordering is
// done here: fill-reducing orderings are the solver's business.
#pragma once
#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "fem/element_dofs.hpp"
#include "linalg/sparse_matrix.hpp"

namespace aster::fem {

class AssemblyPattern {
 public:
  AssemblyPattern(int dofCount, const ElementDofs& elements);

  int dofCount() const { return dofCount_; }
  long long nonZeros() const { return nonZeros_; }
  int elementCount() const { return elements_.elementCount(); }
  const ElementDofs& elements() const { return elements_; }

  // A matrix with the pattern and all values zero.
  linalg::SparseMatrix newMatrix() const;
  // Hands the pattern's own matrix (values zero) over to A, swapped, not copied (Eigen 3.4's
  // sparse matrices have no move): a large model's matrix is hundreds of MB, and memory
  // touched for the first time is slow to get (page faults). newMatrix() and takeMatrix()
  // cannot be called after.
  void takeMatrix(linalg::SparseMatrix& A);
  // Sets all values of a matrix from newMatrix() to zero, keeping the pattern.
  static void clear(linalg::SparseMatrix& A) { std::fill(A.valuePtr(), A.valuePtr() + A.nonZeros(), 0.0); }

  // Positions in the value array of element e's entries, column-major over the
  // local (n x n) matrix: entry (i, j) at [j*n + i]; -1 where not assembled.
  const int* positions(int e) const { return positions_.get() + positionOffsets_[e]; }

  // A += Ke for element e; Ke is the local (n x n) matrix, column-major.
  void addMatrix(int e, const double* Ke, double* values) const {
    const int n = elements_.size(e);
    const int* pos = positions(e);
    for (int k = 0; k < n * n; ++k)
      if (pos[k] >= 0) values[pos[k]] += Ke[k];
  }
  template <class Derived>
  void addMatrix(int e, const Eigen::PlainObjectBase<Derived>& Ke, linalg::SparseMatrix& A) const {
    static_assert(!Derived::IsRowMajor, "element matrices must be column-major");
    checkSize(e, static_cast<int>(Ke.rows()), static_cast<int>(Ke.cols()), A);
    addMatrix(e, Ke.data(), A.valuePtr());
  }

  // F += fe for element e.
  void addVector(int e, const double* fe, double* F) const {
    const int n = elements_.size(e);
    const int* d = elements_.dofs(e);
    for (int i = 0; i < n; ++i)
      if (d[i] >= 0) F[d[i]] += fe[i];
  }
  template <class Derived>
  void addVector(int e, const Eigen::PlainObjectBase<Derived>& fe, Eigen::VectorXd& F) const {
    addVector(e, fe.data(), F.data());
  }

  // Gathers the element's values from a global vector (0 for negative DOFs).
  void gather(int e, const double* U, double* ue) const {
    const int n = elements_.size(e);
    const int* d = elements_.dofs(e);
    for (int i = 0; i < n; ++i) ue[i] = d[i] >= 0 ? U[d[i]] : 0.0;
  }

 private:
  void checkSize(int e, int rows, int cols, const linalg::SparseMatrix& A) const;

  int dofCount_ = 0;
  ElementDofs elements_;
  linalg::SparseMatrix pattern_;
  bool taken_ = false;
  long long nonZeros_ = 0;
  std::vector<std::int64_t> positionOffsets_;
  std::unique_ptr<int[]> positions_;  // -1: an entry of a negative DOF, never assembled
};

// Greedy colouring: elements of one colour share no DOF, so each colour can be
// assembled in parallel without races. Returns the elements of each colour.
std::vector<std::vector<int>> colourElements(const ElementDofs& elements, int dofCount);

}  // namespace aster::fem
