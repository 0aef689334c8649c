// code_aster's GCPC: the conjugate gradient preconditioned by a complete factorization of
// an earlier matrix (PRE_COND='LDLT_SP': MUMPS in single precision; 'LDLT_DP': in double),
// for symmetric positive definite matrices (the stiffness with the imposed displacements
// eliminated). factorize() keeps the matrix and refactorizes the preconditioner only on the
// first call and when the previous solve needed more than REAC_PRECOND iterations; a solve
// that does not converge within NMAX_ITER iterations with a preconditioner of an earlier
// matrix is done again once with a fresh one. In a Newton loop the tangent changes little
// from one iteration to the next: a few iterations replace most factorizations.
//
// statistics(): factorizeCount counts the factorizations of the preconditioner (not the
// calls to factorize()), krylovIterations the conjugate gradient's iterations.
#pragma once
#include <memory>
#include <string>

#include "linalg/linear_solver.hpp"
#include "linalg/sparsity_pattern.hpp"

namespace aster::linalg {

// The SOLVEUR keywords of METHODE='GCPC'.
struct GcpcOptions {
  std::string preconditioner = "LDLT_SP";  // PRE_COND: LDLT_SP or LDLT_DP
  int reacPrecond = 30;           // REAC_PRECOND: refactorize after a solve of more iterations
  double relativeResidual = 1e-6;  // RESI_RELA: stop at ||b - A x|| <= RESI_RELA ||b||
  int maxIterations = 0;          // NMAX_ITER; 0: max(10, n / 2) as code_aster
  int pivotPercent = 20;          // PCENT_PIVOT of the preconditioner's factorization
};

class GcpcSolver : public LinearSolver {
 public:
  GcpcSolver();
  ~GcpcSolver() override;

  void analyze(const SparseMatrix& A) override;
  void factorize(const SparseMatrix& A) override;
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const override;
  std::string name() const override { return "GCPC"; }

  // Throws aster::Error on a value outside those GcpcOptions lists (LDLT_INC, JACOBI, ... by name).
  void setOptions(const GcpcOptions& options);
  const GcpcOptions& options() const { return options_; }
  // Iterations of the last solve (after its second chance, if it took one).
  int lastIterations() const { return lastIterations_; }

 private:
  struct Outcome {
    int iterations = 0;
    double residual = 0;  // ||b - A x|| / ||b||
    bool converged = false;
  };
  Outcome conjugateGradient(const Eigen::VectorXd& b, Eigen::VectorXd& x, int maxIterations) const;
  void refreshPreconditioner() const;
  void requireSymmetric(const SparseMatrix& M) const;

  GcpcOptions options_;
  std::unique_ptr<LinearSolver> preconditioner_;
  std::unique_ptr<SymmetryCheck> symmetry_;
  SparseMatrix matrix_;  // the matrix of the solves
  bool factorized_ = false;
  mutable bool preconditionerCurrent_ = false;  // factorized from matrix_ itself
  mutable bool preconditionerReady_ = false;
  mutable int lastIterations_ = 0;
};

}  // namespace aster::linalg
