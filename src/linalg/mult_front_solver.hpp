// MULT_FRONT, the default of SOLVEUR/METHODE (code_aster's name for its multifrontal
// LDL^T without pivoting): aster-lite's multifrontal factorization with signed pivots
// (CholmodSolver::Mode::MultFront, held in multFront_) for symmetric matrices, positive definite or stiffness +
// Lagrange multipliers (contact, each after the unknowns it ties: setMultipliersFrom). UMFPACK, LU with
// pivoting, takes over for the rest of the run when a matrix is not symmetric (a follower
// pressure) or meets a pivot that a factorization without pivoting cannot take (zero, or
// more than NPREC digits lost); the hand-over is said once. A matrix UMFPACK finds singular
// too is reported as UMFPACK reports it.
//
// SSNP150 modelization A (1705 unknowns, DISCRETE contact): its 47 factorizations take
// 0.16 s with UMFPACK, 0.03-0.05 s here.
#pragma once
#include <functional>
#include <memory>

#include "linalg/cholmod_solver.hpp"
#include "linalg/linear_solver.hpp"

namespace aster::linalg {

class MultFrontSolver : public LinearSolver {
 public:
  MultFrontSolver();
  ~MultFrontSolver() override;

  void analyze(const SparseMatrix& A) override;
  void factorize(const SparseMatrix& A) override;
  void factorizeAndSolve(const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x) override;
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const override;
  void solveMany(const Eigen::MatrixXd& B, Eigen::MatrixXd& X) const override;
  std::string name() const override { return "MULT_FRONT"; }
  std::vector<std::string> orderings() const override { return {"AUTO", "AMD", "METIS", "SANS"}; }

  // Why UMFPACK took over; empty while the multifrontal factorization serves.
  const std::string& handedOver() const { return handedOver_; }

 private:
  void handOver(const std::string& why, const SparseMatrix& A);
  bool tryMultFront(const SparseMatrix& A, const std::function<void()>& multFrontWork);
  void gatherStatistics() const;  // stats_: both solvers' totals, the last one's facts
  LinearSolver& active() const;

  std::unique_ptr<CholmodSolver> multFront_;  // Mode::MultFront
  std::unique_ptr<LinearSolver> umfpack_;  // once handed over
  std::string handedOver_;
};

}  // namespace aster::linalg
