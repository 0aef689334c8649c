// The program's one sparse matrix type: compressed sparse columns of doubles
// with int indices, the layout CHOLMOD, UMFPACK and KLU read without a copy.
#pragma once
#include <algorithm>
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

// A <- (A + A^T) / 2, in place, on a structurally symmetric pattern (every
// entry (i, j) has its (j, i)): the symmetric part of a tangent (MATR_RIGI_SYME).
inline void symmetrizeValues(SparseMatrix& A) {
  A.makeCompressed();
  const int* outer = A.outerIndexPtr();
  const int* rows = A.innerIndexPtr();
  double* values = A.valuePtr();
  for (int j = 0; j < A.outerSize(); ++j)
    for (int p = outer[j]; p < outer[j + 1]; ++p) {
      const int i = rows[p];
      if (i <= j) continue;  // each pair once, from its lower entry
      const int* begin = rows + outer[i];
      const int* end = rows + outer[i + 1];
      const int* at = std::lower_bound(begin, end, j);  // (j, i): row j of column i
      const int q = static_cast<int>(at - rows);
      const double mean = 0.5 * (values[p] + values[q]);
      values[p] = values[q] = mean;
    }
}

}  // namespace aster::linalg
