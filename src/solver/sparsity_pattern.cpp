#include "solver/sparsity_pattern.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.hpp"

namespace aster::solver {

using Matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

void SparsityPattern::record(const Matrix& A) {
  const int n = static_cast<int>(A.cols());
  outer_.assign(A.outerIndexPtr(), A.outerIndexPtr() + n + 1);
  inner_.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
}

void SparsityPattern::requireSame(const Matrix& A, const std::string& method) const {
  if (outer_.empty())
    throw Error(method + ": factorize() called before analyze(); analyze the sparsity pattern first");
  const int n = static_cast<int>(A.cols());
  if (n != size() || A.nonZeros() != static_cast<Eigen::Index>(inner_.size()) ||
      !std::equal(outer_.begin(), outer_.end(), A.outerIndexPtr()) ||
      !std::equal(inner_.begin(), inner_.end(), A.innerIndexPtr())) {
    std::ostringstream s;
    s << method << ": the matrix given to factorize() (" << A.rows() << "x" << A.cols() << ", " << A.nonZeros()
      << " stored entries) does not have the sparsity pattern given to analyze() (" << size() << "x" << size()
      << ", " << inner_.size() << " stored entries); call analyze() again for a new pattern";
    throw Error(s.str());
  }
}

const Matrix& compressedMatrix(const Matrix& A, Matrix& storage) {
  if (A.isCompressed()) return A;
  storage = A;
  storage.makeCompressed();
  return storage;
}

void requireSquare(const Matrix& A, const std::string& method) {
  if (A.rows() != A.cols() || A.rows() == 0) {
    std::ostringstream s;
    s << method << ": expected a non-empty square matrix, got " << A.rows() << "x" << A.cols();
    throw Error(s.str());
  }
}

void requireSymmetric(const Matrix& A, double relTol, const std::string& method) {
  const Matrix At = A.transpose();
  // Both expressions have the union pattern of A and A^T (Eigen keeps cancelled zeros), so
  // their entries can be walked in lockstep.
  const Matrix difference = A - At;
  const Matrix scale = A.cwiseAbs() + At.cwiseAbs();
  // Round-off on an entry is relative to the diagonal too: a_ij = 1e-17 against
  // a_ji = 0 next to diagonals of order 1 is symmetric for every purpose.
  const Eigen::VectorXd diagonal = A.diagonal().cwiseAbs();
  for (int j = 0; j < difference.outerSize(); ++j) {
    Matrix::InnerIterator d(difference, j);
    Matrix::InnerIterator m(scale, j);
    for (; d && m; ++d, ++m) {
      const double size = m.value() + std::sqrt(diagonal(d.index()) * diagonal(j));
      if (std::abs(d.value()) > relTol * size) {
        const int i = static_cast<int>(d.index());
        std::ostringstream s;
        s.precision(17);
        s << method << " needs a symmetric matrix, but A(" << i << "," << j << ") = " << entryOf(A, i, j) << " and A("
          << j << "," << i << ") = " << entryOf(A, j, i)
          << "; use UMFPACK, KLU or EIGEN_LU for an unsymmetric matrix";
        throw Error(s.str());
      }
    }
  }
}

double entryOf(const Matrix& A, int row, int col) {
  for (Matrix::InnerIterator it(A, col); it; ++it)
    if (it.index() == row) return it.value();
  return 0.0;
}

}  // namespace aster::solver
