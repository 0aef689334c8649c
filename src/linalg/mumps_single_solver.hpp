// MUMPS in single precision (SMUMPS of Debian's sequential build, libmumps-seq-dev 5.5): the
// factorization GCPC's PRE_COND='LDLT_SP' preconditions with. The matrix comes in double and
// is rounded to float; the solve takes and gives doubles, computed in float. A symmetric
// matrix only (the lower triangle is read), factorized as general symmetric, L D L^T with
// 1x1 and 2x2 pivots (SYM = 2), after MUMPS's scaling: half the memory and about half the
// time of the double precision factorization, a solution exact to about 1e-7 relative.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "linalg/linear_solver.hpp"

namespace aster::linalg {

class MumpsSingleSolver : public LinearSolver {
 public:
  MumpsSingleSolver();
  ~MumpsSingleSolver() override;
  MumpsSingleSolver(const MumpsSingleSolver&) = delete;
  MumpsSingleSolver& operator=(const MumpsSingleSolver&) = delete;

  void analyze(const SparseMatrix& A) override;    // A symmetric: the caller checked it
  void factorize(const SparseMatrix& A) override;
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const override;
  std::string name() const override { return "MUMPS (single precision)"; }

  // PCENT_PIVOT: ICNTL(14), the workspace margin for delayed pivots, in percent (>= 1).
  void setPivotPercent(int percent);

 private:
  struct Handle;  // smumps_c.h's structure, kept out of this header
  void loadValues(const SparseMatrix& M);

  std::unique_ptr<Handle> h_;
  int pivotPercent_ = 20;
  bool factorized_ = false;
  std::vector<int> irn_, jcn_;  // 1-based coordinates of the lower triangle's entries
  std::vector<int> entries_;    // index of each of them in the matrix's values
  std::vector<float> values_;
  mutable std::vector<float> rhs_;
};

}  // namespace aster::linalg
