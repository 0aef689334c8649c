#include "linalg/eigen_lu_solver.hpp"

#include <Eigen/SparseLU>
#include <string>

#include "linalg/pivot_audit.hpp"
#include "linalg/stopwatch.hpp"

namespace aster::linalg {

namespace {

// where[j] = i when the permutation sends i to j; entries never reached stay -1.
Eigen::VectorXi inverseOf(const Eigen::VectorXi& sendsTo) {
  Eigen::VectorXi where = Eigen::VectorXi::Constant(sendsTo.size(), -1);
  for (int i = 0; i < sendsTo.size(); ++i)
    if (sendsTo[i] >= 0 && sendsTo[i] < sendsTo.size()) where[sendsTo[i]] = i;
  return where;
}

}  // namespace

// SparseLU keeps U's diagonal inside its supernodal L storage (as its own determinant
// functions read it); this subclass exposes the pivots and the factor sizes.
class EigenLuSolver::Factor : public Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> {
 public:
  // SparseLU factors Pr A Pc^-1 = L U: pivot j sits at row Pr^-1(j), column Pc^-1(j) of A.
  Pivot pivot(const SparseMatrix& A, int j, const Eigen::VectorXi& rowOf, const Eigen::VectorXi& colOf) const {
    double u = 0.0;
    for (SCMatrix::InnerIterator it(m_Lstore, j); it; ++it)
      if (it.index() == j) {
        u = it.value();
        break;
      }
    const int row = rowOf[j], col = colOf[j];
    return Pivot{u, entryOf(A, row, col), row, col};
  }
  long long factorNonzeros() const { return static_cast<long long>(m_nnzL) + m_nnzU; }
};

EigenLuSolver::EigenLuSolver() : lu_(std::make_unique<Factor>()) {}
EigenLuSolver::~EigenLuSolver() = default;

void EigenLuSolver::analyze(const SparseMatrix& A) {
  ScopedSeconds t(stats_.analyzeSeconds, stats_.analyzeCount);
  requireSquare(A, name());
  SparseMatrix storage;
  const SparseMatrix& M = compressedMatrix(A, storage);
  factorized_ = false;
  pattern_.record(M);
  lu_->analyzePattern(M);
  stats_.ordering = "COLAMD";
}

void EigenLuSolver::factorize(const SparseMatrix& A) {
  ScopedSeconds t(stats_.factorizeSeconds, stats_.factorizeCount);
  SparseMatrix storage;
  const SparseMatrix& M = compressedMatrix(A, storage);
  pattern_.requireSame(M, name());
  factorized_ = false;
  lu_->factorize(M);
  const int n = pattern_.size();
  const Eigen::VectorXi colOf = inverseOf(lu_->colsPermutation().indices());
  if (lu_->info() != Eigen::Success) {
    // SparseLU reports an exactly zero pivot as "... ZERO COLUMN AT <j+1>", j in the permuted numbering.
    const std::string message = lu_->lastErrorMessage();
    const std::string marker = "ZERO COLUMN AT ";
    const auto at = message.find(marker);
    if (at == std::string::npos) throw Error("EIGEN_LU: numeric factorization failed: " + message);
    const int j = std::stoi(message.substr(at + marker.size())) - 1;
    throwZeroPivot(name(), j >= 0 && j < n ? colOf[j] : -1, -1);
  }
  const Eigen::VectorXi rowOf = inverseOf(lu_->rowsPermutation().indices());
  stats_.factorNonzeros = lu_->factorNonzeros();
  stats_.factorFlops = -1.0;  // SparseLU does not count them
  auditPivots(name(), n, nprec_, [&](int j) { return lu_->pivot(M, j, rowOf, colOf); });
  factorized_ = true;
}

void EigenLuSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  ScopedSeconds t(stats_.solveSeconds, stats_.solveCount);
  requireReadyToSolve(factorized_, b);
  x = lu_->solve(b);
  if (lu_->info() != Eigen::Success) throw Error("EIGEN_LU: solve failed: " + lu_->lastErrorMessage());
}

}  // namespace aster::linalg
