// MUMPS, code_aster's direct solver: Debian's sequential build (libmumps-seq-dev, 5.5), real
// double precision, in one process (the library's own stand-in for MPI). A symmetric matrix
// (MechanicalSystem's symmetric tangents, stiffness + Lagrange multipliers) is factorized as
// general symmetric, L D L^T with 1x1 and 2x2 pivots (SYM = 2), reading the lower triangle;
// any other matrix by LU with partial pivoting (SYM = 0). A matrix analysed as symmetric that
// comes unsymmetric to factorize() (a follower pressure) turns the solver unsymmetric for
// the rest of the run.
//
// Singularity: MUMPS's null pivot detection (ICNTL(24)) stops a factorization whose pivot
// row falls below 10^-NPREC times the infinity norm of the (scaled) matrix; with NPREC <= 0
// only a row that is exactly zero does. This is MUMPS's own criterion, relative to the
// whole matrix, where MULT_FRONT compares each pivot with the entry it started from.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "linalg/linear_solver.hpp"
#include "linalg/sparsity_pattern.hpp"

namespace aster::linalg {

// The SOLVEUR keywords of METHODE='MUMPS' that steer the library.
struct MumpsOptions {
  std::string symmetry = "AUTO";  // TYPE_RESOL: AUTO (the matrix's own), NONSYM, SYMGEN, SYMDEF
  int pivotPercent = 20;          // PCENT_PIVOT: ICNTL(14), workspace margin for delayed pivots
  bool preprocess = true;         // PRETRAITEMENTS='AUTO': scaling and permutation (ICNTL(6), ICNTL(8))
  std::string refinement = "AUTO";  // POSTTRAITEMENTS: SANS/AUTO none, MINI one step, FORCE up to 10
  double residualTolerance = -1.0;  // RESI_RELA > 0: a solution of larger relative residual is refused
};

class MumpsSolver : public LinearSolver {
 public:
  MumpsSolver();
  ~MumpsSolver() override;
  MumpsSolver(const MumpsSolver&) = delete;
  MumpsSolver& operator=(const MumpsSolver&) = delete;

  void analyze(const SparseMatrix& A) override;
  void factorize(const SparseMatrix& A) override;
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const override;
  std::string name() const override { return "MUMPS"; }
  // The orderings Debian's sequential build has (no METIS in it: see mumps_solver.cpp).
  std::vector<std::string> orderings() const override;

  // Throws aster::Error on a value outside those MumpsOptions lists.
  void setOptions(const MumpsOptions& options);
  const MumpsOptions& options() const { return options_; }
  // 0: LU (SYM = 0), 1: symmetric positive definite (SYM = 1), 2: general symmetric; -1 before analyze().
  int symmetryMode() const { return sym_; }
  // MUMPS's estimate of the memory of the last factorization (INFOG(22)), MB; -1 before.
  int factorMegabytes() const { return factorMegabytes_; }

 private:
  struct Handle;  // dmumps_c.h's structure, kept out of this header
  void start(int sym);
  void loadValues(const SparseMatrix& A);
  void runAnalysis();
  void runFactorization();
  void applyControls();

  MumpsOptions options_;
  std::unique_ptr<Handle> h_;
  int sym_ = -1;
  int pivotPercent_ = 20;  // ICNTL(14) in use: raised once when the workspace was short
  int factorMegabytes_ = -1;
  bool factorized_ = false;
  std::unique_ptr<SymmetryCheck> symmetry_;
  SparseMatrix matrix_;           // the last factorized matrix (residual check, iterative refinement)
  std::vector<int> irn_, jcn_;    // 1-based coordinates of the entries given to MUMPS
  std::vector<int> entries_;      // index in matrix_'s values of each of them
  std::vector<double> values_;
  mutable std::vector<double> rhs_;
};

}  // namespace aster::linalg
