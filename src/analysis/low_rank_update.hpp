// Solves a linear system whose matrix differs from a factorized one in the
// equations (rows, and optionally columns) of a few unknowns, from that
// factorization (the Sherman-Morrison-Woodbury formula): the active-set loop
// of static_nonlinear.cpp, where a contact multiplier's release turns its
// equation from a weighted-gap row into lambda = 0.
//
// With M factorized and M' = M + sum_t u_t v_t^T (a row change of unknown i:
// u = e_i, v = new row - old row; a column change: u = new column - old
// column off the diagonal, v = e_i), M' x = b' is solved as
//   y = M^-1 b',  Z = M^-1 [u_t],  w = (I + V^T Z)^-1 V^T y,
//   x = y - Z w = M^-1 (b' - U w),
// with M^-1 b' = x0 + M^-1 (b' - b) from the solution x0 of M x0 = b (b'
// differs from b in the changed rows only). Each M^-1 u costs a solve, kept for the next
// call (the same M): one per unknown whose row changes (none when unknown i is
// decoupled in M: its row and column hold their diagonal only), one more when its
// column changes too; those of one call are one solve with as many right-hand
// sides. Only `rows` of them are kept (the rows where the changes are, and where
// their caller reads x between calls): x there is y - Z w; the whole x takes one
// more solve, M^-1 (b' - U w).
#pragma once
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "analysis/additional_terms.hpp"
#include "linalg/linear_solver.hpp"
#include "linalg/sparse_matrix.hpp"

namespace aster::analysis {

class LowRankUpdate {
 public:
  // M: the matrix `solver` holds factorized (structurally symmetric pattern,
  // the fixed unknowns' rows and columns replaced by the identity's); b and
  // x0: the right-hand side and solution of the solve done with it.
  // rows: the kept rows, every unknown the changes' rows and columns hold.
  LowRankUpdate(const linalg::LinearSolver& solver, const linalg::SparseMatrix& M, const std::vector<char>& fixed,
                const Eigen::VectorXd& b, const Eigen::VectorXd& x0, std::vector<int> rows);
  // x solving the system with `changes` (each of a different unknown; rhs and
  // row before elimination: the fixed unknowns' terms go to the right-hand
  // side with their values x0): on the kept rows only (x0 elsewhere), or,
  // when `full`, everywhere. False when that system is singular.
  bool solve(const std::vector<AdditionalTerms::StatusChange>& changes, Eigen::VectorXd& x, bool full);
  int solves() const { return solves_; }
  // The solves a call would add for `changes` (columns not kept yet).
  int solvesNeeded(const std::vector<AdditionalTerms::StatusChange>& changes) const;

 private:
  using Sparse = std::vector<std::pair<int, double>>;
  Sparse oldRow(int i) const;
  bool decoupled(int i) const;
  void inverseTimes(const std::vector<std::pair<int, Sparse>>& columns);
  std::map<int, double> freeRow(const AdditionalTerms::StatusChange& c) const;
  Sparse columnChange(int i, const std::map<int, double>& row) const;

  const linalg::LinearSolver& solver_;
  const linalg::SparseMatrix& M_;
  const std::vector<char>& fixed_;
  const Eigen::VectorXd& b_;
  const Eigen::VectorXd& x0_;
  std::vector<int> rows_;  // the kept rows
  std::vector<int> at_;    // per unknown: its place in rows_, or -1
  std::map<int, Eigen::VectorXd> kept_;  // M^-1 u on the kept rows by key: 2 i for e_i, 2 i + 1 for unknown i's column change
  int solves_ = 0;
};

}  // namespace aster::analysis
