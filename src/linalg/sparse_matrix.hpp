// The program's one sparse matrix type: compressed sparse columns of doubles
// with int indices, the layout CHOLMOD, UMFPACK and KLU read without a copy.
#pragma once
#include <vector>

#include <Eigen/SparseCore>

namespace aster::linalg {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

// Rows and columns of the fixed unknowns replaced by the identity's, in place (a
// symmetric matrix stays symmetric): how imposed values are eliminated. The
// pattern must hold every diagonal entry of a fixed unknown.
inline void eliminateFixedUnknowns(SparseMatrix& A, const std::vector<char>& fixed) {
  A.makeCompressed();
  const int* outer = A.outerIndexPtr();
  const int* rows = A.innerIndexPtr();
  double* values = A.valuePtr();
  for (int j = 0; j < A.outerSize(); ++j)
    for (int p = outer[j]; p < outer[j + 1]; ++p)
      if (fixed[j] || fixed[rows[p]]) values[p] = rows[p] == j ? 1.0 : 0.0;
}

}  // namespace aster::linalg
