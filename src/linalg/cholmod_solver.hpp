// CHOLMOD for symmetric matrices (only the upper triangle is read, after a symmetry check).
// Mode::Cholesky: supernodal LL^T (BLAS/LAPACK on dense blocks), ordering chosen by CHOLMOD
//   (AMD, or nested dissection on large matrices factorized many times); the matrix must be positive definite.
//   CHOLMOD computes the ordering, the supernodes and the solves; the numeric factorization
//   is aster-lite's multifrontal one (multifrontal_cholesky.hpp), several times faster
//   than CHOLMOD's left-looking one on 2D meshes.
// Mode::LDLT: simplicial LDL^T without pivoting. Rows whose diagonal is absent or zero when
//   analyze() runs (Lagrange multipliers) are ordered after all others (constrained AMD), so
//   that a stiffness + constraints system [K B^T; B 0] with K positive definite and B of full
//   rank factors stably (it is quasi-definite in that order). Other indefinite matrices may
//   meet a zero pivot, which is reported; use UMFPACK for general symmetric indefinite systems.
// Mode::MultFront: MULT_FRONT's factorization, the multifrontal one of Mode::Cholesky with
//   signed pivots, P A P^T = L S L^T, S = diag(+-1), without pivoting
//   (multifrontal_cholesky.hpp): a positive definite matrix takes exactly the Cholesky path,
//   and a stiffness + Lagrange multipliers system (constraint rows as for Mode::LDLT) the
//   Cholesky speed. MultFrontSolver (mult_front_solver.hpp) owns the one solver in this mode.
#pragma once
#include <memory>

#include "linalg/linear_solver.hpp"
#include "linalg/multifrontal_cholesky.hpp"
#include "linalg/warmed_block.hpp"

namespace aster::linalg {

class CholmodSolver : public LinearSolver {
 public:
  enum class Mode { Cholesky, LDLT, MultFront };
  explicit CholmodSolver(Mode mode);
  ~CholmodSolver() override;
  CholmodSolver(const CholmodSolver&) = delete;
  CholmodSolver& operator=(const CholmodSolver&) = delete;

  void analyze(const SparseMatrix& A) override;
  void factorize(const SparseMatrix& A) override;
  void factorizeAndSolve(const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x) override;
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const override;
  void solveMany(const Eigen::MatrixXd& B, Eigen::MatrixXd& X) const override;
  std::string name() const override {
    return mode_ == Mode::Cholesky ? "CHOLMOD" : mode_ == Mode::LDLT ? "CHOLMOD_LDLT" : "MULT_FRONT";
  }
  Mode mode() const { return mode_; }
  // RENUM: AUTO (AMD; nested dissection on large matrices factorized many times), AMD, METIS, SANS (natural).
  // CHOLMOD_LDLT and MULT_FRONT with constraint rows always order them last (constrained AMD).
  std::vector<std::string> orderings() const override { return {"AUTO", "AMD", "METIS", "SANS"}; }

  // Relative tolerance of the symmetry check, per pair A(i,j), A(j,i). Default 1e-10.
  void setSymmetryTolerance(double relTol) { symmetryTolerance_ = relTol; }

 private:
  struct Handles;  // cholmod.h's structures, kept out of this header
  void planMultifrontal(const SparseMatrix& A, const std::vector<int>& constraintSet);
  void auditFactor(const SparseMatrix& A) const;
  Mode mode_;
  double symmetryTolerance_ = 1e-10;
  void factorizeWith(const SparseMatrix& A, double* forward);
  Eigen::MatrixXd toFactorOrder(const double* B, Eigen::Index k) const;
  void fromFactorOrder(const Eigen::MatrixXd& Y, double* X) const;
  bool factorized_ = false;
  std::unique_ptr<Handles> h_;
  std::unique_ptr<SymmetryCheck> symmetry_;              // once analysed
  std::unique_ptr<MultifrontalCholesky> multifrontal_;
  std::unique_ptr<WarmedBlock> factorStorage_;           // the multifrontal factor's values
  double* values() const { return factorStorage_->data(); }  // with multifrontal_ only
  std::vector<double> pivots_;  // L(k,k) from the multifrontal factorization, times S(k,k)
  bool negativePivots_ = false;  // S != I: solve() applies S between the triangular solves
};

}  // namespace aster::linalg
