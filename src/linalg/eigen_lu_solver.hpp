// Eigen's SparseLU (supernodal LU with partial pivoting, COLAMD ordering): no external library.
#pragma once
#include <memory>

#include "linalg/linear_solver.hpp"

namespace aster::linalg {

class EigenLuSolver : public LinearSolver {
 public:
  EigenLuSolver();
  ~EigenLuSolver() override;

  void analyze(const SparseMatrix& A) override;
  void factorize(const SparseMatrix& A) override;
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const override;
  std::string name() const override { return "EIGEN_LU"; }
  std::vector<std::string> orderings() const override { return {"AUTO", "COLAMD"}; }

 private:
  class Factor;  // SparseLU with access to its pivots
  std::unique_ptr<Factor> lu_;
  bool factorized_ = false;
};

}  // namespace aster::linalg
