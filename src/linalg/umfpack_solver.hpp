// UMFPACK: unsymmetric multifrontal LU with row scaling and iterative refinement.
#pragma once
#include "linalg/linear_solver.hpp"

namespace aster::linalg {

class UmfpackSolver : public LinearSolver {
 public:
  UmfpackSolver();
  ~UmfpackSolver() override;
  UmfpackSolver(const UmfpackSolver&) = delete;
  UmfpackSolver& operator=(const UmfpackSolver&) = delete;

  void analyze(const SparseMatrix& A) override;
  void factorize(const SparseMatrix& A) override;
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const override;
  std::string name() const override { return "UMFPACK"; }
  std::vector<std::string> orderings() const override { return {"AUTO", "AMD", "COLAMD", "METIS", "SANS"}; }

 private:
  void auditFactor() const;
  void freeNumeric();
  void freeSymbolic();

  double control_[20];
  mutable double info_[90];
  void* symbolic_ = nullptr;
  void* numeric_ = nullptr;
  SparseMatrix matrix_;  // the factorized values, needed by iterative refinement in solve()
};

}  // namespace aster::linalg
