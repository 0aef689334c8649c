// The sparsity pattern a symbolic analysis was made for, and checks on input matrices.
#pragma once
#include <Eigen/SparseCore>
#include <string>
#include <vector>

namespace aster::solver {

class SparsityPattern {
 public:
  // Records A's pattern. A must be compressed.
  void record(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& A);
  bool empty() const { return outer_.empty(); }
  int size() const { return outer_.empty() ? 0 : static_cast<int>(outer_.size()) - 1; }
  // Throws aster::Error unless A (compressed) has exactly the recorded pattern.
  void requireSame(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& A, const std::string& method) const;

 private:
  std::vector<int> outer_;
  std::vector<int> inner_;
};

// Returns A itself when it is compressed, otherwise a compressed copy kept in storage.
const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& compressedMatrix(
    const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& A,
    Eigen::SparseMatrix<double, Eigen::ColMajor, int>& storage);

// Throws aster::Error unless A is square and non-empty.
void requireSquare(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& A, const std::string& method);

// Throws aster::Error at the first pair A(i,j), A(j,i) that differ by more than
// relTol * max(|A(i,j)|, |A(j,i)|) (an absent entry counts as 0).
void requireSymmetric(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& A, double relTol,
                      const std::string& method);

// A(row, col), 0 when the entry is not stored. Linear in the column's length.
double entryOf(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& A, int row, int col);

}  // namespace aster::solver
