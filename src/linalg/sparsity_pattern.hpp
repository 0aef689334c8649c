// The sparsity pattern a symbolic analysis was made for, and checks on input matrices.
#pragma once
#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "linalg/sparse_matrix.hpp"

namespace aster::linalg {

// What requireSymmetric and SymmetryCheck throw: a matrix that is not symmetric.
class UnsymmetricMatrixError : public Error {
 public:
  using Error::Error;
};

class SparsityPattern {
 public:
  // Records A's pattern. A must be compressed.
  void record(const SparseMatrix& A);
  bool empty() const { return outer_.empty(); }
  int size() const { return outer_.empty() ? 0 : static_cast<int>(outer_.size()) - 1; }
  // Throws aster::Error unless A (compressed) has exactly the recorded pattern.
  void requireSame(const SparseMatrix& A, const std::string& method) const;

 private:
  std::vector<int> outer_;
  std::vector<int> inner_;
};

// Returns A itself when it is compressed, otherwise a compressed copy kept in storage.
const SparseMatrix& compressedMatrix(
    const SparseMatrix& A,
    SparseMatrix& storage);

// Throws aster::Error unless A is square and non-empty.
void requireSquare(const SparseMatrix& A, const std::string& method);

// Throws UnsymmetricMatrixError at the first pair A(i,j), A(j,i) that differ by more than
// relTol * (|A(i,j)| + |A(j,i)| + sqrt(|A(i,i) A(j,j)|)) (an absent entry counts as 0; the
// diagonals count because a_ij = 1e-17 against a_ji = 0 next to diagonals of order 1 is
// symmetric for every purpose). A SymmetryCheck of A's pattern, made for this one call.
void requireSymmetric(const SparseMatrix& A, double relTol,
                      const std::string& method);

// requireSymmetric for many matrices of one pattern (a Newton loop): the pairs of mirror
// entries are found once, then each check is one pass over them (SVK square N = 256:
// 56 ms -> a few ms per factorization). A(i,i) comes without a search.
class SymmetryCheck {
 public:
  // Records A's pattern (compressed; rows sorted in each column, or every check falls back
  // to requireSymmetric).
  // With mirrors false, only the diagonal (for diagonal()): the caller vouches for the
  // symmetry, and require() throws aster::Error.
  explicit SymmetryCheck(const SparseMatrix& A, bool mirrors = true);
  // Same test and message as requireSymmetric; A has the recorded pattern.
  void require(const SparseMatrix& A, double relTol,
               const std::string& method) const;
  // A(j, j), 0 when not stored.
  double diagonal(const SparseMatrix& A, int j) const {
    return diagonal_[j] < 0 ? 0.0 : A.valuePtr()[diagonal_[j]];
  }

 private:
  bool sorted_ = true;
  bool mirrorsRecorded_ = true;
  std::vector<int> diagonal_;  // index of A(j,j) in the values, -1 when absent
  std::vector<std::pair<int, int>> mirrors_;  // indices of A(i,j) and A(j,i), i > j
  std::vector<int> alone_;     // off-diagonal entries whose mirror is not stored
};

// A(row, col), 0 when the entry is not stored. Linear in the column's length.
double entryOf(const SparseMatrix& A, int row, int col);

}  // namespace aster::linalg
