#include "linalg/sparsity_pattern.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <sstream>

#include "core/error.hpp"
#include "core/worker_pool.hpp"

namespace aster::linalg {


void SparsityPattern::record(const SparseMatrix& A) {
  const int n = static_cast<int>(A.cols());
  outer_.assign(A.outerIndexPtr(), A.outerIndexPtr() + n + 1);
  inner_.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
}

void SparsityPattern::requireSame(const SparseMatrix& A, const std::string& method) const {
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

const SparseMatrix& compressedMatrix(const SparseMatrix& A, SparseMatrix& storage) {
  if (A.isCompressed()) return A;
  storage = A;
  storage.makeCompressed();
  return storage;
}

void requireSquare(const SparseMatrix& A, const std::string& method) {
  if (A.rows() != A.cols() || A.rows() == 0) {
    std::ostringstream s;
    s << method << ": expected a non-empty square matrix, got " << A.rows() << "x" << A.cols();
    throw Error(s.str());
  }
}

namespace {

[[noreturn]] void throwUnsymmetric(const SparseMatrix& A, int i, int j, const std::string& method) {
  std::ostringstream s;
  s.precision(17);
  s << method << " needs a symmetric matrix, but A(" << i << "," << j << ") = " << entryOf(A, i, j) << " and A(" << j
    << "," << i << ") = " << entryOf(A, j, i) << "; use UMFPACK, KLU or EIGEN_LU for an unsymmetric matrix";
  throw UnsymmetricMatrixError(s.str());
}

bool rowsSorted(const SparseMatrix& A) {
  const int* p = A.outerIndexPtr();
  const int* r = A.innerIndexPtr();
  for (int j = 0; j < A.cols(); ++j)
    for (int k = p[j] + 1; k < p[j + 1]; ++k)
      if (r[k] <= r[k - 1]) return false;
  return true;
}

}  // namespace

void requireSymmetric(const SparseMatrix& A, double relTol, const std::string& method) {
  if (A.isCompressed() && rowsSorted(A)) {
    SymmetryCheck(A).require(A, relTol, method);
    return;
  }
  const SparseMatrix transposed = A.transpose();
  const SparseMatrix sorted = transposed.transpose();  // compressed, rows sorted
  SymmetryCheck(sorted).require(sorted, relTol, method);
}

// One pass over the entries without building A^T: column j's entries below the diagonal,
// (i, j) with i > j, are met for increasing j, so their mirrors (j, i) come in row order in
// column i; a cursor per column walks them. Upper entries the cursor skips have no mirror.
SymmetryCheck::SymmetryCheck(const SparseMatrix& A, bool mirrors) : mirrorsRecorded_(mirrors) {
  sorted_ = A.isCompressed() && rowsSorted(A);
  if (!sorted_) return;
  const int n = static_cast<int>(A.cols());
  const int* p = A.outerIndexPtr();
  const int* r = A.innerIndexPtr();
  diagonal_.assign(n, -1);
  if (!mirrors) {
    for (int j = 0; j < n; ++j)
      for (int k = p[j]; k < p[j + 1]; ++k)
        if (r[k] == j) diagonal_[j] = k;
    return;
  }
  std::vector<int> cursor(p, p + n);
  for (int j = 0; j < n; ++j)
    for (int k = p[j]; k < p[j + 1]; ++k) {
      const int i = r[k];
      if (i == j) diagonal_[j] = k;
      if (i <= j) continue;
      int& c = cursor[i];
      for (; c < p[i + 1] && r[c] < j; ++c) alone_.push_back(c);  // upper entries without a mirror
      if (c < p[i + 1] && r[c] == j)
        mirrors_.emplace_back(k, c++);
      else
        alone_.push_back(k);
    }
  for (int i = 0; i < n; ++i)
    for (int c = cursor[i]; c < p[i + 1] && r[c] < i; ++c) alone_.push_back(c);
}

void SymmetryCheck::require(const SparseMatrix& A, double relTol, const std::string& method) const {
  if (!mirrorsRecorded_) throw Error("internal error: " + method + " checks a symmetry it was told to trust");
  if (!sorted_) {
    requireSymmetric(A, relTol, method);
    return;
  }
  const int* r = A.innerIndexPtr();
  const double* v = A.valuePtr();
  const int n = static_cast<int>(A.cols());
  std::vector<double> d(n);
  for (int j = 0; j < n; ++j) d[j] = std::abs(diagonal(A, j));
  auto pairFails = [&](std::size_t e) {
    const auto [k, c] = mirrors_[e];
    const double a = v[k], b = v[c];
    return std::abs(a - b) > relTol * (std::abs(a) + std::abs(b) + std::sqrt(d[r[k]] * d[r[c]]));
  };
  // Both cores look for a failure; the first one, in a fixed order, is then named.
  const long long pairs = static_cast<long long>(mirrors_.size());
  std::atomic<bool> failed{false};
  constexpr long long kSlice = 1 << 16;
  const int slices = static_cast<int>((pairs + kSlice - 1) / kSlice);
  WorkerPool::shared().forEach(slices, [&](int k) {
    for (long long e = k * kSlice; e < std::min(pairs, (k + 1) * kSlice) && !failed.load(std::memory_order_relaxed); ++e)
      if (pairFails(static_cast<std::size_t>(e))) failed = true;
  });
  if (failed)
    for (std::size_t e = 0; e < mirrors_.size(); ++e)
      if (pairFails(e)) throwUnsymmetric(A, r[mirrors_[e].first], r[mirrors_[e].second], method);
  auto columnOf = [&](int k) {
    return static_cast<int>(std::upper_bound(A.outerIndexPtr(), A.outerIndexPtr() + n + 1, k) - A.outerIndexPtr()) - 1;
  };
  for (int k : alone_) {
    const int i = r[k], j = columnOf(k);
    if (std::abs(v[k]) > relTol * (std::abs(v[k]) + std::sqrt(d[i] * d[j]))) throwUnsymmetric(A, i, j, method);
  }
}

double entryOf(const SparseMatrix& A, int row, int col) {
  for (SparseMatrix::InnerIterator it(A, col); it; ++it)
    if (it.index() == row) return it.value();
  return 0.0;
}

}  // namespace aster::linalg
