// Sparse direct solvers chosen by name, as code_aster's SOLVEUR/METHODE.
// analyze() once per sparsity pattern, factorize() at each Newton iteration
// (same pattern, new values), solve() for each right-hand side.
#pragma once
#include <Eigen/SparseCore>
#include <memory>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "linalg/sparse_matrix.hpp"
#include "linalg/sparsity_pattern.hpp"

namespace aster::linalg {

// A singular or numerically singular matrix. column/row are the original (0-based)
// indices of the failing pivot when the library tells them, -1 otherwise, so that
// a caller can map them to a node and a component.
class SingularMatrixError : public Error {
 public:
  SingularMatrixError(const std::string& what, int column, int row)
      : Error(what), column_(column), row_(row) {}
  int column() const { return column_; }
  int row() const { return row_; }

 private:
  int column_;
  int row_;
};

struct LinearSolverStatistics {
  double analyzeSeconds = 0.0;    // totals over all calls
  double factorizeSeconds = 0.0;
  double solveSeconds = 0.0;
  int analyzeCount = 0;
  int factorizeCount = 0;
  int solveCount = 0;
  long long factorNonzeros = -1;  // entries stored in the factors after the last factorize; -1: unknown
  double factorFlops = -1.0;      // flops of the last factorization as the library reports them; -1: not reported
  double numericSeconds = 0.0;    // the numeric factorizations alone (library call), total
  double firstNumericSeconds = 0.0;  // the first of them, which also touches the factor's memory first
  std::string ordering;           // fill-reducing ordering the analysis chose, when the library tells it
  long long krylovIterations = 0;  // iterative solvers (GCPC): iterations over all solves
};

class LinearSolver {
 public:
  virtual ~LinearSolver();
  virtual void analyze(const SparseMatrix& A) = 0;    // symbolic, once per sparsity pattern
  virtual void factorize(const SparseMatrix& A) = 0;  // numeric, same pattern as analyze()
  virtual void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const = 0;
  // One solve per column of B. The multifrontal factor reads L once for all of them
  // (BLAS 3 instead of 2); the other solvers solve the columns one by one.
  virtual void solveMany(const Eigen::MatrixXd& B, Eigen::MatrixXd& X) const;
  // factorize(A), then solve(b, x), as one call: MULT_FRONT takes each front's step of the
  // forward substitution while the factorization has it in cache.
  virtual void factorizeAndSolve(const SparseMatrix& A, const Eigen::VectorXd& b, Eigen::VectorXd& x);
  virtual std::string name() const = 0;

  const LinearSolverStatistics& statistics() const { return stats_; }

  // code_aster's NPREC: a pivot that lost more than nprec significant digits with
  // respect to the matrix entry it started from makes the matrix numerically
  // singular. nprec <= 0 keeps only the exact-zero pivot test. Default 8.
  void setSingularityDigits(int nprec) { nprec_ = nprec; }
  int singularityDigits() const { return nprec_; }

  // code_aster's SOLVEUR/RENUM: the fill-reducing ordering the next analyze() uses.
  // Each solver honours the names orderings() lists ("AUTO": its own choice, "SANS":
  // none); another throws aster::Error listing them.
  void setOrdering(const std::string& renum);
  const std::string& ordering() const { return ordering_; }
  virtual std::vector<std::string> orderings() const { return {"AUTO"}; }

  // How many factorizations the caller expects per analysis: many in a Newton loop
  // (the default), one for a linear solve. RENUM='AUTO' weighs the cost of computing
  // an ordering against the flops it saves over all of them.
  void setFactorizationsPerAnalysis(int n) { factorizationsPerAnalysis_ = n; }

  // Unknowns first, first + 1, ... are Lagrange multipliers (contact): the factorizations
  // without pivoting order each after the unknowns it ties, whatever their diagonal. -1: none.
  void setMultipliersFrom(int first) { multipliersFrom_ = first; }

  // The caller vouches that every matrix it gives is exactly symmetric (MechanicalSystem::
  // symmetricTangent): the solvers for symmetric matrices then skip their check of the
  // values, a pass over the matrix at each factorization (4 % of the SVK square at N = 256).
  void setSymmetricByConstruction(bool yes) { symmetricByConstruction_ = yes; }

 protected:
  // Throws unless a factorization is ready and b has as many entries as the matrix has rows.
  void requireReadyToSolve(bool factorized, const Eigen::VectorXd& b) const;

  mutable LinearSolverStatistics stats_;  // solve() is const but counts its time
  int nprec_ = 8;
  std::string ordering_ = "AUTO";
  int multipliersFrom_ = -1;
  bool symmetricByConstruction_ = false;
  int factorizationsPerAnalysis_ = 1000;
  SparsityPattern pattern_;  // what analyze() saw, to refuse another pattern in factorize()
};

// The direct solvers makeLinearSolver accepts (it also takes the iterative 'GCPC').
std::vector<std::string> linearSolverMethods();

// 'MULT_FRONT' (the default: multifrontal, signed pivots, symmetric matrices; UMFPACK takes
// over for others, mult_front_solver.hpp), 'MUMPS' (mumps_solver.hpp), 'UMFPACK', 'CHOLMOD' (supernodal LL^T, symmetric
// positive definite only), 'CHOLMOD_LDLT' (simplicial LDL^T without pivoting, for symmetric
// quasi-definite systems such as stiffness + Lagrange multipliers), 'KLU', 'EIGEN_LU', and the
// iterative 'GCPC' (conjugate gradient for symmetric positive definite matrices, gcpc_solver.hpp).
// Throws aster::Error on an unknown name, listing the allowed ones.
std::unique_ptr<LinearSolver> makeLinearSolver(const std::string& methode);

}  // namespace aster::linalg
