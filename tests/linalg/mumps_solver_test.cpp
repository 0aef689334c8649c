// MUMPS (Debian's sequential build) against known solutions, with each ordering it has.
// The checks every solver passes (singular matrices, NPREC, call order) are in
// linear_solver_test.cpp, which runs them on MUMPS too.
#include "linalg/mumps_solver.hpp"

#include <gtest/gtest.h>

#include <string>

#include "test_matrices.hpp"

namespace aster::linalg {
namespace {

using namespace testing;

// Solves A x = A x_known; returns the relative error of x.
double solveKnown(MumpsSolver& solver, const SparseMatrix& A) {
  const Eigen::VectorXd xKnown = knownSolution(static_cast<int>(A.rows()));
  const Eigen::VectorXd b = A * xKnown;
  solver.analyze(A);
  solver.factorize(A);
  Eigen::VectorXd x;
  solver.solve(b, x);
  EXPECT_LT(relativeResidual(A, x, b), 1e-12) << solver.ordering();
  return (x - xKnown).norm() / xKnown.norm();
}

class MumpsOrdering : public ::testing::TestWithParam<std::string> {};

TEST_P(MumpsOrdering, SolvesSymmetricPositiveDefinite) {
  MumpsSolver solver;
  solver.setOrdering(GetParam());
  EXPECT_LT(solveKnown(solver, laplacian2d(15)), 1e-11);
  EXPECT_EQ(solver.symmetryMode(), 2);  // general symmetric, the lower triangle
  if (GetParam() != "AUTO") {
    EXPECT_EQ(solver.statistics().ordering, GetParam());
  }
  // L holds at least the lower triangle of A: 225 + 2*14*15 entries.
  EXPECT_GE(solver.statistics().factorNonzeros, 225 + 2 * 14 * 15);
  EXPECT_GT(solver.statistics().factorFlops, 0.0);
}

TEST_P(MumpsOrdering, SolvesSaddlePointWithLagrangeMultipliers) {
  // [K B^T; B 0]: symmetric indefinite, zero diagonal on the multipliers.
  MumpsSolver solver;
  solver.setOrdering(GetParam());
  EXPECT_LT(solveKnown(solver, saddlePoint(10, 5)), 1e-9);
  EXPECT_EQ(solver.symmetryMode(), 2);
}

TEST_P(MumpsOrdering, SolvesSymmetricIndefinite) {
  // Laplacian shifted by -3.3: 28 negative eigenvalues of 81, cond ~ 170.
  MumpsSolver solver;
  solver.setOrdering(GetParam());
  EXPECT_LT(solveKnown(solver, laplacian2d(9, -3.3)), 1e-10);
  EXPECT_EQ(solver.symmetryMode(), 2);
}

TEST_P(MumpsOrdering, SolvesUnsymmetric) {
  MumpsSolver solver;
  solver.setOrdering(GetParam());
  EXPECT_LT(solveKnown(solver, convectionDiffusion(11, 2.5)), 1e-11);
  EXPECT_EQ(solver.symmetryMode(), 0);  // LU
}

INSTANTIATE_TEST_SUITE_P(Renum, MumpsOrdering, ::testing::Values("AUTO", "AMD", "AMF", "QAMD", "PORD", "SCOTCH"),
                         [](const auto& info) { return info.param; });

// PORD ends the process on a dense matrix (one element's stiffness; from one unknown up):
// such a matrix, which no ordering can make sparser, is ordered by AMD.
TEST(Mumps, PordIsNotGivenADenseMatrix) {
  for (int n : {1, 2, 16}) {
    Triplets t;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) t.emplace_back(i, j, i == j ? n + 1.0 : 1.0);  // diagonally dominant
    MumpsSolver solver;
    solver.setOrdering("PORD");
    EXPECT_LT(solveKnown(solver, fromTriplets(n, t)), 1e-13) << n;
    EXPECT_EQ(solver.statistics().ordering, "AMD (a dense matrix, which PORD cannot order)") << n;
  }
}

TEST(Mumps, OrderingsOfOtherBuildsAreRefusedByName) {
  MumpsSolver solver;
  for (const char* renum : {"METIS", "PARMETIS", "PTSCOTCH"}) {
    try {
      solver.setOrdering(renum);
      FAIL() << renum << " accepted";
    } catch (const Error& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(std::string("RENUM='") + renum + "'"), std::string::npos) << what;
      EXPECT_NE(what.find("'SCOTCH'"), std::string::npos) << what;
    }
  }
}

TEST(Mumps, SingularSaddlePointIsRefused) {
  // The same constraint twice: B has dependent rows, [K B^T; B 0] is singular.
  Triplets t;
  laplacian2d(8, t);
  for (int c = 0; c < 2; ++c) {
    t.emplace_back(64 + c, 5, 1.0);
    t.emplace_back(5, 64 + c, 1.0);
    t.emplace_back(64 + c, 20, -1.0);
    t.emplace_back(20, 64 + c, -1.0);
  }
  const SparseMatrix A = fromTriplets(66, t);
  MumpsSolver solver;
  solver.analyze(A);
  EXPECT_THROW(solver.factorize(A), SingularMatrixError);
  Eigen::VectorXd x;
  EXPECT_THROW(solver.solve(Eigen::VectorXd::Ones(66), x), Error);
}

TEST(Mumps, ASymmetricPatternWithUnsymmetricValuesTurnsToLu) {
  // Analysed symmetric, then a follower-pressure-like unsymmetric matrix of the same pattern.
  const SparseMatrix symmetric = laplacian2d(9);
  Triplets t;
  laplacian2d(9, t);
  t.emplace_back(3, 4, 0.7);  // adds to A(3,4) only
  const SparseMatrix unsymmetric = fromTriplets(81, t);
  MumpsSolver solver;
  solver.analyze(symmetric);
  solver.factorize(symmetric);
  EXPECT_EQ(solver.symmetryMode(), 2);
  solver.factorize(unsymmetric);
  EXPECT_EQ(solver.symmetryMode(), 0);
  const Eigen::VectorXd xKnown = knownSolution(81), b = unsymmetric * xKnown;
  Eigen::VectorXd x;
  solver.solve(b, x);
  EXPECT_LT((x - xKnown).norm() / xKnown.norm(), 1e-12);
}

TEST(Mumps, TypeResolChoosesTheFactorization) {
  MumpsOptions o;
  o.symmetry = "SYMDEF";
  MumpsSolver definite;
  definite.setOptions(o);
  EXPECT_LT(solveKnown(definite, laplacian2d(10)), 1e-12);
  EXPECT_EQ(definite.symmetryMode(), 1);
  o.symmetry = "NONSYM";
  MumpsSolver lu;
  lu.setOptions(o);
  EXPECT_LT(solveKnown(lu, laplacian2d(10)), 1e-12);
  EXPECT_EQ(lu.symmetryMode(), 0);
  // Declared symmetric, an unsymmetric matrix is refused rather than half read.
  o.symmetry = "SYMGEN";
  MumpsSolver general;
  general.setOptions(o);
  general.analyze(convectionDiffusion(5, 1.0));
  EXPECT_THROW(general.factorize(convectionDiffusion(5, 1.0)), Error);
  o.symmetry = "SYMETRIQUE";
  EXPECT_THROW(general.setOptions(o), Error);
}

TEST(Mumps, ResiRelaRefusesASolutionAboveTheTolerance) {
  // The residual of a direct solve is of the order of the round-off, ~1e-16 here: 1e-10
  // accepts it, 1e-30 cannot be met.
  const SparseMatrix A = laplacian2d(10);
  const Eigen::VectorXd b = A * knownSolution(100);
  MumpsOptions o;
  o.residualTolerance = 1e-10;
  MumpsSolver solver;
  solver.setOptions(o);
  solver.analyze(A);
  solver.factorize(A);
  Eigen::VectorXd x;
  EXPECT_NO_THROW(solver.solve(b, x));
  o.residualTolerance = 1e-30;
  solver.setOptions(o);
  try {
    solver.solve(b, x);
    FAIL() << "a residual below 1e-30 accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("RESI_RELA"), std::string::npos) << e.what();
  }
}

TEST(Mumps, RefinementAndPreprocessingOptionsSolveAlike) {
  for (const char* refinement : {"SANS", "MINI", "FORCE"})
    for (bool preprocess : {true, false}) {
      MumpsOptions o;
      o.refinement = refinement;
      o.preprocess = preprocess;
      o.pivotPercent = 50;
      MumpsSolver solver;
      solver.setOptions(o);
      EXPECT_LT(solveKnown(solver, saddlePoint(10, 5)), 1e-9) << refinement << preprocess;
    }
  MumpsOptions bad;
  bad.pivotPercent = 0;
  MumpsSolver solver;
  EXPECT_THROW(solver.setOptions(bad), Error);
}

TEST(Mumps, PrintsNothing) {
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  MumpsSolver solver;
  const double error = solveKnown(solver, saddlePoint(12, 6));
  Triplets t;
  laplacian2d(6, t);
  t.emplace_back(40, 40, 0.0);  // a null row and column
  MumpsSolver singular;
  const SparseMatrix S = fromTriplets(41, t);
  singular.analyze(S);
  EXPECT_THROW(singular.factorize(S), SingularMatrixError);
  const std::string out = ::testing::internal::GetCapturedStdout(), err = ::testing::internal::GetCapturedStderr();
  EXPECT_LT(error, 1e-9);
  EXPECT_EQ(out, "");
  EXPECT_EQ(err, "");
}

}  // namespace
}  // namespace aster::linalg
