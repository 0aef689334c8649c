// GCPC: the conjugate gradient preconditioned by a MUMPS factorization (single or double
// precision) of an earlier matrix, against direct solves and its own counts.
#include "linalg/gcpc_solver.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "linalg/mumps_single_solver.hpp"
#include "linalg/mult_front_solver.hpp"
#include "test_matrices.hpp"

namespace aster::linalg {
namespace {

using namespace testing;

std::unique_ptr<GcpcSolver> gcpc(const std::string& preconditioner, int reacPrecond = 30, double resiRela = 1e-6,
                                 int nmaxIter = 0) {
  auto s = std::make_unique<GcpcSolver>();
  GcpcOptions o;
  o.preconditioner = preconditioner;
  o.reacPrecond = reacPrecond;
  o.relativeResidual = resiRela;
  o.maxIterations = nmaxIter;
  s->setOptions(o);
  return s;
}

Eigen::VectorXd directSolve(const SparseMatrix& A, const Eigen::VectorXd& b) {
  MultFrontSolver direct;
  direct.analyze(A);
  direct.factorize(A);
  Eigen::VectorXd x;
  direct.solve(b, x);
  return x;
}

// A with its diagonal scaled unknown by unknown between 1 and 1 + spread (same pattern, SPD).
SparseMatrix scaledDiagonal(const SparseMatrix& A, double spread) {
  SparseMatrix B = A;
  for (int j = 0; j < B.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(B, j); it; ++it)
      if (it.row() == j) it.valueRef() *= 1.0 + spread * (0.5 + 0.5 * std::sin(0.7 * j));
  return B;
}

class Preconditioner : public ::testing::TestWithParam<std::string> {};

TEST_P(Preconditioner, ReachesTheAskedResidualAgainstADirectSolve) {
  // 5-point Laplacian on 40 x 40 nodes: cond ~ 660. The preconditioner is the factorization of
  // this matrix: single precision leaves an error of ~1e-7 cond per iteration, double none.
  const SparseMatrix A = laplacian2d(40);
  const Eigen::VectorXd b = A * knownSolution(1600);
  const Eigen::VectorXd xDirect = directSolve(A, b);
  for (double resi : {1e-6, 1e-10, 1e-13}) {
    auto owner = gcpc(GetParam(), 30, resi);
    GcpcSolver& s = *owner;
    s.analyze(A);
    s.factorize(A);
    Eigen::VectorXd x;
    s.solve(b, x);
    EXPECT_LE(relativeResidual(A, x, b), resi) << resi;
    // ||x - x*|| / ||x*|| <= cond(A) ||r|| / ||b||
    EXPECT_LE((x - xDirect).norm() / xDirect.norm(), 660 * resi) << resi;
    EXPECT_LE(s.lastIterations(), GetParam() == "LDLT_DP" ? 2 : 6) << resi;
    EXPECT_EQ(s.statistics().factorizeCount, 1);
    EXPECT_EQ(s.statistics().krylovIterations, s.lastIterations());
  }
}

TEST_P(Preconditioner, KeepsThePreconditionerWhileSolvesTakeAtMostReacPrecondIterations) {
  // Five matrices close to each other (diagonals 1 % apart): with the first one's
  // factorization, the conjugate gradient needs a few iterations, fewer than REAC_PRECOND = 30.
  const SparseMatrix A0 = laplacian2d(30);
  const Eigen::VectorXd b = A0 * knownSolution(900);
  auto owner = gcpc(GetParam());
  GcpcSolver& s = *owner;
  s.analyze(A0);
  for (int k = 0; k < 5; ++k) {
    const SparseMatrix A = scaledDiagonal(A0, 0.01 * k);
    s.factorize(A);
    Eigen::VectorXd x;
    s.solve(b, x);
    EXPECT_LE(relativeResidual(A, x, b), 1e-6);
    EXPECT_GT(s.lastIterations(), 0);
    EXPECT_LE(s.lastIterations(), 30);
  }
  EXPECT_EQ(s.statistics().factorizeCount, 1);
  EXPECT_EQ(s.statistics().solveCount, 5);
}

TEST_P(Preconditioner, RefactorizesAfterASolveOfMoreThanReacPrecondIterations) {
  // REAC_PRECOND = 0: every solve takes at least one iteration, so each factorize() after a
  // solve factorizes again. REAC_PRECOND = 3 with a matrix 100 % off on its diagonal: the
  // solve takes more than 3 iterations, the next factorize() refactorizes, and the solve
  // after it, with the factorization of its own matrix, takes fewer.
  const SparseMatrix A0 = laplacian2d(30);
  const Eigen::VectorXd b = A0 * knownSolution(900);
  {
    auto owner = gcpc(GetParam(), 0);
    GcpcSolver& s = *owner;
    s.analyze(A0);
    for (int k = 0; k < 4; ++k) {
      s.factorize(scaledDiagonal(A0, 0.01 * k));
      Eigen::VectorXd x;
      s.solve(b, x);
      EXPECT_EQ(s.statistics().factorizeCount, k + 1);
    }
  }
  auto owner = gcpc(GetParam(), 3);
  GcpcSolver& s = *owner;
  s.analyze(A0);
  s.factorize(A0);
  Eigen::VectorXd x;
  s.solve(b, x);
  const SparseMatrix far = scaledDiagonal(A0, 1.0);
  s.factorize(far);  // the last solve took <= 3 iterations: the preconditioner is kept
  EXPECT_EQ(s.statistics().factorizeCount, 1);
  s.solve(b, x);
  EXPECT_LE(relativeResidual(far, x, b), 1e-6);
  ASSERT_GT(s.lastIterations(), 3);
  s.factorize(far);  // now it is not
  EXPECT_EQ(s.statistics().factorizeCount, 2);
  s.solve(b, x);
  EXPECT_LE(relativeResidual(far, x, b), 1e-6);
  EXPECT_LE(s.lastIterations(), 3);
}

TEST_P(Preconditioner, AFarMatrixForcesAFreshFactorizationWithinTheSolve) {
  // NMAX_ITER = 4 and a matrix 10 times off on parts of its diagonal: the preconditioner
  // of A0 does not converge in 4 iterations, the one of the matrix itself does.
  const SparseMatrix A0 = laplacian2d(30);
  const SparseMatrix far = scaledDiagonal(A0, 10.0);
  const Eigen::VectorXd b = A0 * knownSolution(900);
  auto owner = gcpc(GetParam(), 30, 1e-6, 4);
  GcpcSolver& s = *owner;
  s.analyze(A0);
  s.factorize(A0);
  Eigen::VectorXd x;
  s.solve(b, x);
  s.factorize(far);
  EXPECT_EQ(s.statistics().factorizeCount, 1);
  s.solve(b, x);
  EXPECT_EQ(s.statistics().factorizeCount, 2);
  EXPECT_LE(relativeResidual(far, x, b), 1e-6);
  EXPECT_LE(s.lastIterations(), 4);
  EXPECT_GT(s.statistics().krylovIterations, 4 + s.lastIterations());  // the failed attempt counts
}

INSTANTIATE_TEST_SUITE_P(Gcpc, Preconditioner, ::testing::Values("LDLT_SP", "LDLT_DP"),
                         [](const auto& info) { return info.param; });

TEST(Gcpc, StopsWhenEvenAFreshPreconditionerDoesNotConverge) {
  // Single precision cannot reach 1e-14 in one iteration (its error is ~1e-7 cond).
  const SparseMatrix A = laplacian2d(30);
  auto owner = gcpc("LDLT_SP", 30, 1e-14, 1);
  GcpcSolver& s = *owner;
  s.analyze(A);
  s.factorize(A);
  Eigen::VectorXd x;
  try {
    s.solve(A * knownSolution(900), x);
    FAIL() << "converged in one iteration to 1e-14";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("GCPC"), std::string::npos) << what;
    EXPECT_NE(what.find("NMAX_ITER = 1"), std::string::npos) << what;
  }
  EXPECT_EQ(s.statistics().factorizeCount, 1);  // already the matrix's own: no second chance
}

TEST(Gcpc, NmaxIterZeroIsHalfTheUnknowns) {
  // A preconditioner from a matrix 10 times off on parts of its diagonal: the conjugate
  // gradient needs more than 10 iterations, fewer than 450. NMAX_ITER = 0 allows 450 on
  // 900 unknowns: the solve keeps the preconditioner; NMAX_ITER = 10 takes a second chance.
  const SparseMatrix A0 = laplacian2d(30);
  const Eigen::VectorXd b = A0 * knownSolution(900);
  for (int nmaxIter : {0, 10}) {
    auto owner = gcpc("LDLT_DP", 1000, 1e-6, nmaxIter);
    GcpcSolver& s = *owner;
    s.analyze(A0);
    s.factorize(scaledDiagonal(A0, 10.0));
    s.factorize(A0);  // the preconditioner stays the first matrix's
    Eigen::VectorXd x;
    s.solve(b, x);
    EXPECT_LE(relativeResidual(A0, x, b), 1e-6);
    if (nmaxIter == 0) {
      EXPECT_GT(s.lastIterations(), 10);
      EXPECT_EQ(s.statistics().factorizeCount, 1);
    } else {
      EXPECT_EQ(s.statistics().factorizeCount, 2);
    }
  }
}

TEST(Gcpc, RefusesAnUnsymmetricMatrixByName) {
  auto owner = gcpc("LDLT_SP");
  GcpcSolver& s = *owner;
  try {
    s.analyze(convectionDiffusion(10, 0.5));
    FAIL() << "analysed an unsymmetric matrix";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("GCPC"), std::string::npos) << what;
    EXPECT_NE(what.find("symmetric positive definite"), std::string::npos) << what;
  }
  // And one that turns unsymmetric after a symmetric analysis.
  SparseMatrix A = laplacian2d(10);
  s.analyze(A);
  A.coeffRef(1, 0) = -2.0;
  EXPECT_THROW(s.factorize(A), Error);
}

TEST(Gcpc, RefusesContactMultipliersByName) {
  const SparseMatrix A = saddlePoint(10, 5);
  auto owner = gcpc("LDLT_SP");
  GcpcSolver& s = *owner;
  s.setMultipliersFrom(100);
  try {
    s.analyze(A);
    FAIL() << "analysed a saddle point";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("GCPC"), std::string::npos) << what;
    EXPECT_NE(what.find("Lagrange multipliers"), std::string::npos) << what;
    EXPECT_NE(what.find("positive definite"), std::string::npos) << what;
  }
}

TEST(Gcpc, RefusesANegativeDefiniteMatrix) {
  const SparseMatrix A = -laplacian2d(10);
  auto owner = gcpc("LDLT_DP");
  GcpcSolver& s = *owner;
  s.analyze(A);
  s.factorize(A);
  Eigen::VectorXd x;
  try {
    s.solve(A * knownSolution(100), x);
    FAIL() << "solved a negative definite matrix";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("not positive definite"), std::string::npos) << e.what();
  }
}

TEST(Gcpc, RefusesPreconditionersItDoesNotHaveByName) {
  GcpcSolver s;
  GcpcOptions o;
  for (const char* name : {"LDLT_INC", "JACOBI", "SANS"}) {
    o.preconditioner = name;
    try {
      s.setOptions(o);
      FAIL() << name;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("PRE_COND='") + name + "'"), std::string::npos) << e.what();
    }
  }
}

TEST(Gcpc, MakeLinearSolverBuildsIt) {
  auto s = makeLinearSolver("GCPC");
  EXPECT_EQ(s->name(), "GCPC");
  const SparseMatrix A = laplacian2d(12);
  const Eigen::VectorXd b = A * knownSolution(144);
  s->analyze(A);
  s->factorize(A);
  Eigen::VectorXd x;
  s->solve(b, x);
  EXPECT_LE(relativeResidual(A, x, b), 1e-6);  // RESI_RELA's default
}

TEST(MumpsSingle, SolvesToSinglePrecision) {
  // cond ~ 660: a single precision factorization gives ~1e-7 * 660 relative error.
  const SparseMatrix A = laplacian2d(40);
  const Eigen::VectorXd xKnown = knownSolution(1600);
  MumpsSingleSolver s;
  s.analyze(A);
  s.factorize(A);
  Eigen::VectorXd x;
  s.solve(A * xKnown, x);
  const double error = (x - xKnown).norm() / xKnown.norm();
  EXPECT_LT(error, 660 * 1e-6);
  EXPECT_GT(error, 1e-12);  // and not better than single precision allows: it is single
}

}  // namespace
}  // namespace aster::linalg
