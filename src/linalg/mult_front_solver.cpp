#include "linalg/mult_front_solver.hpp"

#include <functional>

#include "core/messages.hpp"
#include "linalg/umfpack_solver.hpp"

namespace aster::linalg {

MultFrontSolver::MultFrontSolver() : multFront_(std::make_unique<CholmodSolver>(CholmodSolver::Mode::MultFront)) {}

MultFrontSolver::~MultFrontSolver() = default;

LinearSolver& MultFrontSolver::active() const {
  return umfpack_ ? static_cast<LinearSolver&>(*umfpack_) : static_cast<LinearSolver&>(*multFront_);
}

void MultFrontSolver::analyze(const SparseMatrix& A) {
  if (umfpack_) {
    umfpack_->setSingularityDigits(nprec_);
    umfpack_->analyze(A);
  } else {
    multFront_->setOrdering(ordering_);
    multFront_->setSingularityDigits(nprec_);
    multFront_->setMultipliersFrom(multipliersFrom_);
    multFront_->setSymmetricByConstruction(symmetricByConstruction_);
    multFront_->setFactorizationsPerAnalysis(factorizationsPerAnalysis_);
    multFront_->analyze(A);
  }
  gatherStatistics();
}

// Runs `multFrontWork` while the multifrontal factorization holds; a matrix it cannot take
// hands the run over to UMFPACK. True when it ran.
bool MultFrontSolver::tryMultFront(const SparseMatrix& A, const std::function<void()>& multFrontWork) {
  active().setSingularityDigits(nprec_);
  if (umfpack_) return false;
  try {
    multFrontWork();
    gatherStatistics();
    return true;
  } catch (const UnsymmetricMatrixError&) {
    handOver("the matrix is not symmetric", A);
  } catch (const SingularMatrixError& e) {
    const std::string what = e.what(), prefix = name() + ": ";
    handOver("without pivoting, " + (what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what), A);
  }
  return false;
}

void MultFrontSolver::factorize(const SparseMatrix& A) {
  if (tryMultFront(A, [&] { multFront_->factorize(A); })) return;
  umfpack_->factorize(A);
  gatherStatistics();
}

void MultFrontSolver::factorizeAndSolve(const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  if (tryMultFront(A, [&] { multFront_->factorizeAndSolve(A, b, x); })) return;
  umfpack_->factorize(A);
  umfpack_->solve(b, x);
  gatherStatistics();
}

void MultFrontSolver::handOver(const std::string& why, const SparseMatrix& A) {
  handedOver_ = why;
  Messages::info("MULT_FRONT: " + why + "; UMFPACK (LU with pivoting) takes over");
  umfpack_ = std::make_unique<UmfpackSolver>();
  umfpack_->setSingularityDigits(nprec_);
  umfpack_->analyze(A);
}

void MultFrontSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  active().solve(b, x);
  gatherStatistics();
}

void MultFrontSolver::solveMany(const Eigen::MatrixXd& B, Eigen::MatrixXd& X) const {
  active().solveMany(B, X);
  gatherStatistics();
}

void MultFrontSolver::gatherStatistics() const {
  const LinearSolverStatistics& s = multFront_->statistics();
  stats_ = umfpack_ ? umfpack_->statistics() : s;
  if (!umfpack_) return;
  stats_.analyzeSeconds += s.analyzeSeconds;
  stats_.factorizeSeconds += s.factorizeSeconds;
  stats_.solveSeconds += s.solveSeconds;
  stats_.analyzeCount += s.analyzeCount;
  stats_.factorizeCount += s.factorizeCount;
  stats_.solveCount += s.solveCount;
  stats_.numericSeconds += s.numericSeconds;
}

}  // namespace aster::linalg
