// KLU: LU with block triangular form, suited to circuit-like very sparse matrices.
#pragma once
#include <memory>

#include "linalg/linear_solver.hpp"

namespace aster::linalg {

class KluSolver : public LinearSolver {
 public:
  KluSolver();
  ~KluSolver() override;
  KluSolver(const KluSolver&) = delete;
  KluSolver& operator=(const KluSolver&) = delete;

  void analyze(const SparseMatrix& A) override;
  void factorize(const SparseMatrix& A) override;
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const override;
  std::string name() const override { return "KLU"; }
  std::vector<std::string> orderings() const override { return {"AUTO", "AMD", "COLAMD", "SANS"}; }

 private:
  struct Handles;  // klu.h's structures, kept out of this header
  void freeNumeric();
  void freeSymbolic();
  void auditFactor(const SparseMatrix& A) const;
  std::unique_ptr<Handles> h_;
};

}  // namespace aster::linalg
