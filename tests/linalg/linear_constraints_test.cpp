#include "linalg/linear_constraints.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "linalg/sparsity_pattern.hpp"

namespace aster::linalg {
namespace {

constexpr int kN = 8;

// A symmetric positive definite stiffness-like matrix with a sparse pattern: a
// chain of springs with a diagonal that differs from node to node.
SparseMatrix stiffness() {
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(kN, kN);
  for (int i = 0; i + 1 < kN; ++i) {
    const double k = 1.0 + 0.37 * i;
    K(i, i) += k, K(i + 1, i + 1) += k, K(i, i + 1) -= k, K(i + 1, i) -= k;
  }
  for (int i = 0; i < kN; ++i) K(i, i) += 0.1 * (i + 1);
  K(0, 5) = K(5, 0) = 0.2;
  return K.sparseView();
}

Eigen::VectorXd load() {
  Eigen::VectorXd f(kN);
  f << 1.0, -2.0, 0.5, 3.0, -1.0, 0.25, 2.0, -0.75;
  return f;
}

// The reference: the saddle-point system [K C^T; C 0] [u; lambda] = [f; b], dense,
// with each fixed value as one more relation u_i = g_i.
Eigen::VectorXd lagrangeSolve(const SparseMatrix& Ks, const Eigen::VectorXd& f, const std::vector<LinearRelation>& rel) {
  const int m = static_cast<int>(rel.size());
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(kN + m, kN + m);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(kN + m);
  S.topLeftCorner(kN, kN) = Eigen::MatrixXd(Ks);
  rhs.head(kN) = f;
  for (int k = 0; k < m; ++k) {
    for (const auto& [j, a] : rel[k].terms) S(kN + k, j) += a, S(j, kN + k) += a;
    rhs(kN + k) = rel[k].rhs;
  }
  return S.fullPivLu().solve(rhs).head(kN);
}

Eigen::VectorXd eliminationSolve(const SparseMatrix& K, const Eigen::VectorXd& f, const ConstraintElimination& e) {
  const SparseMatrix A = e.reduce(K);
  const Eigen::VectorXd rhs = e.reduce(Eigen::VectorXd(f - K * e.offset()));
  const Eigen::VectorXd v = Eigen::MatrixXd(A).llt().solve(rhs);
  return e.expand(v);
}

std::vector<char> noneFixed() { return std::vector<char>(kN, 0); }

TEST(ConstraintElimination, SameSolutionAsLagrangeMultipliers) {
  const SparseMatrix K = stiffness();
  const std::vector<LinearRelation> rel = {{{{0, 1.0}, {1, -1.0}}, 0.3}, {{{2, 2.0}, {3, 1.0}, {5, -1.0}}, 1.0}};
  const ConstraintElimination e(kN, noneFixed(), Eigen::VectorXd(), rel);
  EXPECT_EQ(e.slaveCount(), 2);
  const Eigen::VectorXd u = eliminationSolve(K, load(), e);
  const Eigen::VectorXd ref = lagrangeSolve(K, load(), rel);
  EXPECT_LT((u - ref).lpNorm<Eigen::Infinity>(), 1e-12);
  EXPECT_NEAR(u(0) - u(1), 0.3, 1e-14);
  EXPECT_NEAR(2 * u(2) + u(3) - u(5), 1.0, 1e-14);
}

// Fixed values and relations together; a relation through a fixed unknown.
TEST(ConstraintElimination, FixedValuesAndRelations) {
  const SparseMatrix K = stiffness();
  std::vector<char> fixed = noneFixed();
  Eigen::VectorXd values = Eigen::VectorXd::Zero(kN);
  fixed[7] = 1, values(7) = 0.5;
  fixed[4] = 1, values(4) = -0.25;
  const std::vector<LinearRelation> rel = {{{{3, 1.0}, {7, 1.0}}, 1.0}, {{{0, 1.0}, {6, -2.0}}, 0.0}};
  const ConstraintElimination e(kN, fixed, values, rel);
  std::vector<LinearRelation> all = rel;
  all.push_back({{{7, 1.0}}, 0.5});
  all.push_back({{{4, 1.0}}, -0.25});
  const Eigen::VectorXd u = eliminationSolve(K, load(), e);
  EXPECT_LT((u - lagrangeSolve(K, load(), all)).lpNorm<Eigen::Infinity>(), 1e-12);
  EXPECT_EQ(u(7), 0.5);
  EXPECT_NEAR(u(3), 0.5, 1e-15);
}

// u0 = u1, u1 = u2, u2 = u3: each new slave is substituted in the slaves before it.
TEST(ConstraintElimination, ChainedRelations) {
  const SparseMatrix K = stiffness();
  const std::vector<LinearRelation> rel = {{{{0, 1.0}, {1, -1.0}}, 0.0},
                                           {{{1, 1.0}, {2, -1.0}}, 0.1},
                                           {{{2, 1.0}, {3, -1.0}}, 0.0},
                                           {{{1, 3.0}, {6, -1.0}}, 1.0}};
  const ConstraintElimination e(kN, noneFixed(), Eigen::VectorXd(), rel);
  EXPECT_EQ(e.slaveCount(), 4);
  const Eigen::VectorXd u = eliminationSolve(K, load(), e);
  EXPECT_LT((u - lagrangeSolve(K, load(), rel)).lpNorm<Eigen::Infinity>(), 1e-12);
  EXPECT_NEAR(u(0), u(3) + 0.1, 1e-14);
  EXPECT_NEAR(3 * u(1) - u(6), 1.0, 1e-14);
}

// The third relation follows from the first two: skipped, and the solution is that of
// the first two alone.
TEST(ConstraintElimination, RedundantRelationsAreSkipped) {
  const SparseMatrix K = stiffness();
  const std::vector<LinearRelation> rel = {
      {{{0, 1.0}, {1, -1.0}}, 0.2}, {{{1, 2.0}, {2, -2.0}}, 0.6}, {{{0, -0.5}, {2, 0.5}}, -0.25}};
  const ConstraintElimination e(kN, noneFixed(), Eigen::VectorXd(), rel);
  EXPECT_EQ(e.slaveCount(), 2);
  EXPECT_EQ(e.redundantCount(), 1);
  const Eigen::VectorXd u = eliminationSolve(K, load(), e);
  const std::vector<LinearRelation> independent(rel.begin(), rel.begin() + 2);
  EXPECT_LT((u - lagrangeSolve(K, load(), independent)).lpNorm<Eigen::Infinity>(), 1e-12);
  // A relation on fixed unknowns alone that they satisfy is redundant too.
  std::vector<char> fixed = noneFixed();
  Eigen::VectorXd values = Eigen::VectorXd::Zero(kN);
  fixed[1] = fixed[2] = 1, values(1) = 1.0, values(2) = 3.0;
  const ConstraintElimination onFixed(kN, fixed, values, {{{{1, 3.0}, {2, -1.0}}, 0.0}});
  EXPECT_EQ(onFixed.redundantCount(), 1);
}

TEST(ConstraintElimination, ContradictoryRelationsAreRefused) {
  const std::vector<LinearRelation> rel = {
      {{{0, 1.0}, {1, -1.0}}, 0.0}, {{{1, 1.0}, {2, -1.0}}, 0.0}, {{{0, 1.0}, {2, -1.0}}, 1e-3}};
  try {
    ConstraintElimination(kN, noneFixed(), Eigen::VectorXd(), rel);
    FAIL() << "no error";
  } catch (const ContradictoryRelationError& e) {
    EXPECT_EQ(e.relation(), 2);
    EXPECT_NEAR(e.mismatch(), 1e-3, 1e-15);
  }
  // A relation against fixed values.
  std::vector<char> fixed = noneFixed();
  Eigen::VectorXd values = Eigen::VectorXd::Zero(kN);
  fixed[3] = 1, values(3) = 1.0;
  EXPECT_THROW(ConstraintElimination(kN, fixed, values, {{{{3, 2.0}}, 1.0}}), ContradictoryRelationError);
}

// u_i = 1.5 u_0 for i = 1, 2, 3: each relation's first unknown, whose coefficient is at
// least half the largest, is its slave; the shared u_0 stays a master (one term each).
TEST(ConstraintElimination, SharedUnknownStaysMaster) {
  std::vector<LinearRelation> rel;
  for (int i = 1; i <= 3; ++i) rel.push_back({{{i, 1.0}, {0, -1.5}}, 0.0});
  const ConstraintElimination e(kN, noneFixed(), Eigen::VectorXd(), rel);
  EXPECT_FALSE(e.isSlave(0));
  for (int i = 1; i <= 3; ++i) EXPECT_TRUE(e.isSlave(i));
  const Eigen::VectorXd u = eliminationSolve(stiffness(), load(), e);
  EXPECT_LT((u - lagrangeSolve(stiffness(), load(), rel)).lpNorm<Eigen::Infinity>(), 1e-12);
}

TEST(ConstraintElimination, ReducedMatrixIsSymmetricWithIdentityRows) {
  const SparseMatrix K = stiffness();
  std::vector<char> fixed = noneFixed();
  Eigen::VectorXd values = Eigen::VectorXd::Zero(kN);
  fixed[7] = 1;
  const std::vector<LinearRelation> rel = {{{{0, 0.3}, {1, -0.7}, {4, 1.1}}, 0.0}, {{{2, 1.0}, {5, -1.0}}, 0.0}};
  const ConstraintElimination e(kN, fixed, values, rel);
  const SparseMatrix A = e.reduce(K);
  const Eigen::MatrixXd D(A);
  EXPECT_EQ((D - D.transpose()).lpNorm<Eigen::Infinity>(), 0.0);
  for (int i = 0; i < kN; ++i)
    if (e.constrained()[i]) {
      EXPECT_EQ(D(i, i), 1.0);
      EXPECT_EQ(D.row(i).cwiseAbs().sum(), 1.0);
    }
  // Other right-hand sides: the same transformation; another fixed set: not.
  const std::vector<LinearRelation> other = {{{{0, 0.3}, {1, -0.7}, {4, 1.1}}, 2.0}, {{{2, 1.0}, {5, -1.0}}, 1.0}};
  EXPECT_TRUE(e.sameTransformation(ConstraintElimination(kN, fixed, values, other)));
  EXPECT_FALSE(e.sameTransformation(ConstraintElimination(kN, noneFixed(), values, rel)));
}

}  // namespace
}  // namespace aster::linalg
