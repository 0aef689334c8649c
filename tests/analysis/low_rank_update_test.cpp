// LowRankUpdate (the active-set loop's re-solve): the system with changed rows
// and columns, solved from the factorization of the original one, against a
// dense LU of the changed matrix written out by hand.
#include <gtest/gtest.h>

#include <vector>

#include <Eigen/Dense>

#include "analysis/low_rank_update.hpp"
#include "linalg/linear_solver.hpp"

using namespace aster;
using analysis::AdditionalTerms;
using analysis::LowRankUpdate;

namespace {

// A chain of 6 springs (unknowns 0 .. 5, unknown 0 fixed) and two contact
// multipliers: 6 active (a weighted-gap row and column g6), 7 inactive (its
// diagonal S only), as a contact tangent is after elimination.
struct Saddle {
  static constexpr int n = 8;
  double S = 2.5;
  Eigen::VectorXd g6{{0, 0.0, 0.0, 0.0, 1.0, -0.5}}, g7{{0.7, 0.0, 0.0, -0.3, 0.0, 1.0}};
  std::vector<char> fixed = {1, 0, 0, 0, 0, 0, 0, 0};
  Eigen::MatrixXd dense() const {
    Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < 5; ++i) {
      const double k = 1.0 + 0.5 * i;
      M(i, i) += k;
      M(i + 1, i + 1) += k;
      M(i, i + 1) -= k;
      M(i + 1, i) -= k;
    }
    M(5, 5) += 0.8;
    for (int j = 0; j < 6; ++j) {
      M(6, j) = M(j, 6) = S * g6(j);
    }
    M(7, 7) = S;
    // Unknown 0 fixed: the identity's row and column.
    M.row(0).setZero();
    M.col(0).setZero();
    M(0, 0) = 1.0;
    return M;
  }
};

linalg::SparseMatrix sparse(const Eigen::MatrixXd& D) {
  // Every entry of the pattern stored, zeros included (structurally symmetric, as an assembly's).
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < D.cols(); ++j)
    for (int i = 0; i < D.rows(); ++i)
      if (D(i, j) != 0 || D(j, i) != 0 || i == j || (i >= 6 && j < 6) || (j >= 6 && i < 6))
        t.emplace_back(i, j, D(i, j));
  linalg::SparseMatrix A(D.rows(), D.cols());
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  return A;
}

}  // namespace

// Multiplier 6 released (its row becomes S e_6, its column stays), multiplier
// 7 activated (row and column S g7; g7 has a term on the fixed unknown 0,
// moved to the right-hand side).
TEST(LowRankUpdate, SolvesTheChangedSystemFromTheOriginalFactorization) {
  const Saddle s;
  const Eigen::MatrixXd D = s.dense();
  const linalg::SparseMatrix M = sparse(D);
  auto solver = linalg::makeLinearSolver("MULT_FRONT");
  solver->setMultipliersFrom(6);
  solver->analyze(M);
  solver->factorize(M);
  const double dU0 = 0.3, U6 = -0.4, U7 = 0.25, gap6 = 0.01, gap7 = -0.02;
  Eigen::VectorXd b{{dU0, 0.1, -0.2, 0.3, 0.05, -0.15, -s.S * gap6, -s.S * U7}};
  Eigen::VectorXd x0;
  solver->solve(b, x0);
  ASSERT_LT((D * x0 - b).norm(), 1e-12);

  std::vector<AdditionalTerms::StatusChange> changes;
  changes.push_back({6, {{6, s.S}}, -s.S * U6, false});
  std::vector<std::pair<int, double>> row;
  for (int j = 0; j < 6; ++j)
    if (s.g7(j) != 0) row.push_back({j, s.S * s.g7(j)});
  changes.push_back({7, row, -s.S * gap7, true});

  // The changed system, written out.
  Eigen::MatrixXd D2 = D;
  D2.row(6).setZero();
  D2(6, 6) = s.S;
  for (int j = 1; j < 6; ++j) D2(7, j) = D2(j, 7) = s.S * s.g7(j);
  D2(7, 7) = 0.0;
  Eigen::VectorXd b2 = b;
  b2(6) = -s.S * U6;
  b2(7) = -s.S * gap7 - s.S * s.g7(0) * dU0;
  const Eigen::VectorXd expected = D2.fullPivLu().solve(b2);
  ASSERT_LT((D2 * expected - b2).norm(), 1e-12);

  // Kept rows: the changes' unknowns 1 .. 7 (0 is fixed).
  LowRankUpdate update(*solver, M, s.fixed, b, x0, {1, 2, 3, 4, 5, 6, 7});
  // Unknown 6's e_6 (coupled in M), unknown 7's column (e_7 is decoupled: no solve).
  EXPECT_EQ(update.solvesNeeded(changes), 2);
  Eigen::VectorXd kept, full;
  ASSERT_TRUE(update.solve(changes, kept, false));
  EXPECT_EQ(update.solves(), 2);
  EXPECT_EQ(update.solvesNeeded(changes), 0);
  ASSERT_TRUE(update.solve(changes, full, true));
  EXPECT_EQ(update.solves(), 3);  // the whole x: one more solve
  for (int i = 0; i < Saddle::n; ++i) {
    EXPECT_NEAR(full(i), expected(i), 1e-12) << i;
    EXPECT_NEAR(kept(i), expected(i), 1e-12) << i;
  }
}

// No change: the original solution.
TEST(LowRankUpdate, NoChangeGivesTheOriginalSolution) {
  const Saddle s;
  const linalg::SparseMatrix M = sparse(s.dense());
  auto solver = linalg::makeLinearSolver("MULT_FRONT");
  solver->setMultipliersFrom(6);
  solver->analyze(M);
  solver->factorize(M);
  Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(Saddle::n, -1.0, 1.0), x0, x;
  solver->solve(b, x0);
  LowRankUpdate update(*solver, M, s.fixed, b, x0, {1, 2, 3, 4, 5, 6, 7});
  ASSERT_TRUE(update.solve({}, x, false));
  EXPECT_EQ(update.solves(), 0);
  EXPECT_LT((x - x0).norm(), 1e-15);
}
