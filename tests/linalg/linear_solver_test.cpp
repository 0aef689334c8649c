#include "linalg/linear_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>

#include "linalg/mult_front_solver.hpp"
#include "test_matrices.hpp"

namespace aster::linalg {
namespace {

using namespace testing;

// Analyze, factorize, solve A x = A x_known and check residual and error.
void expectSolves(LinearSolver& solver, const SparseMatrix& A, double errorTol = 1e-10) {
  const Eigen::VectorXd xKnown = knownSolution(static_cast<int>(A.rows()));
  const Eigen::VectorXd b = A * xKnown;
  solver.analyze(A);
  solver.factorize(A);
  Eigen::VectorXd x;
  solver.solve(b, x);
  ASSERT_EQ(x.size(), A.rows());
  EXPECT_LT(relativeResidual(A, x, b), 1e-12) << solver.name();
  EXPECT_LT((x - xKnown).norm() / xKnown.norm(), errorTol) << solver.name();
}

class EveryMethod : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryMethod, SolvesSymmetricPositiveDefinite) {
  auto solver = makeLinearSolver(GetParam());
  EXPECT_EQ(solver->name(), GetParam());
  expectSolves(*solver, laplacian2d(12));
  const auto& s = solver->statistics();
  EXPECT_EQ(s.analyzeCount, 1);
  EXPECT_EQ(s.factorizeCount, 1);
  EXPECT_EQ(s.solveCount, 1);
  EXPECT_GE(s.factorizeSeconds, 0.0);
  // L alone holds at least the lower triangle of A: 144 + 2*11*12 entries.
  EXPECT_GE(s.factorNonzeros, 144 + 2 * 11 * 12);
}

TEST_P(EveryMethod, RefactorizesNewValuesWithTheSamePattern) {
  auto solver = makeLinearSolver(GetParam());
  const SparseMatrix A1 = laplacian2d(10);
  solver->analyze(A1);
  solver->factorize(A1);
  const SparseMatrix A2 = laplacian2d(10, 1.5) * 3.0;  // same pattern, other values
  solver->factorize(A2);
  const Eigen::VectorXd xKnown = knownSolution(100);
  const Eigen::VectorXd b = A2 * xKnown;
  Eigen::VectorXd x;
  solver->solve(b, x);
  EXPECT_LT(relativeResidual(A2, x, b), 1e-12);
  EXPECT_LT((x - xKnown).norm() / xKnown.norm(), 1e-12);
  EXPECT_EQ(solver->statistics().analyzeCount, 1);
  EXPECT_EQ(solver->statistics().factorizeCount, 2);
}

TEST_P(EveryMethod, AcceptsUncompressedMatrices) {
  auto solver = makeLinearSolver(GetParam());
  SparseMatrix A = laplacian2d(6);
  A.coeffRef(0, 0) = 5.0;  // keeps the pattern, and the matrix compressed...
  A.uncompress();          // ...until now
  ASSERT_FALSE(A.isCompressed());
  expectSolves(*solver, A);
}

TEST_P(EveryMethod, ExactlySingularMatrixNamesTheZeroColumn) {
  // Column and row 37 are empty apart from an explicit zero diagonal.
  Triplets t;
  laplacian2d(8, t);
  Triplets kept;
  for (const auto& e : t)
    if (e.row() != 37 && e.col() != 37) kept.push_back(e);
  kept.emplace_back(37, 37, 0.0);
  const SparseMatrix A = fromTriplets(64, kept);
  auto solver = makeLinearSolver(GetParam());
  solver->analyze(A);
  try {
    solver->factorize(A);
    FAIL() << GetParam() << " factorized a singular matrix";
  } catch (const SingularMatrixError& e) {
    EXPECT_EQ(e.column(), 37) << e.what();
    EXPECT_NE(std::string(e.what()).find("37"), std::string::npos) << e.what();
  }
  Eigen::VectorXd x;
  EXPECT_THROW(solver->solve(Eigen::VectorXd::Ones(64), x), Error);
}

TEST_P(EveryMethod, FreeStructureIsSingular) {
  // A bar of 49 springs without support: constants are in the kernel. The stiffnesses are not
  // representable exactly, so rounding may leave a tiny last pivot rather than an exact zero.
  const int n = 50;
  Triplets t;
  for (int i = 0; i + 1 < n; ++i) {
    const double k = 1.0 / (0.7 + 0.013 * i);
    t.emplace_back(i, i, k);
    t.emplace_back(i + 1, i + 1, k);
    t.emplace_back(i, i + 1, -k);
    t.emplace_back(i + 1, i, -k);
  }
  const SparseMatrix A = fromTriplets(n, t);
  auto solver = makeLinearSolver(GetParam());
  solver->analyze(A);
  try {
    solver->factorize(A);
    FAIL() << GetParam() << " factorized a singular matrix";
  } catch (const SingularMatrixError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("singular"), std::string::npos) << what;
    EXPECT_NE(what.find("Dirichlet"), std::string::npos) << what;
  }
}

TEST_P(EveryMethod, LosingMoreThanNprecDigitsIsNumericallySingular) {
  // [[1, 1], [1, 1 + 1e-10]]: the second pivot is 1e-10 against an entry of about 1,
  // 10 digits lost: singular for NPREC = 8, accepted for NPREC = 12 or without the test.
  const double eps = 1e-10;
  const SparseMatrix A = fromTriplets(2, {{0, 0, 1.0}, {0, 1, 1.0}, {1, 0, 1.0}, {1, 1, 1.0 + eps}});
  auto solver = makeLinearSolver(GetParam());
  solver->analyze(A);
  try {
    solver->factorize(A);
    FAIL() << GetParam() << " accepted a pivot that lost 10 digits with NPREC = 8";
  } catch (const SingularMatrixError& e) {
    EXPECT_NE(std::string(e.what()).find("numerically singular"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("NPREC = 8"), std::string::npos) << e.what();
  }
  solver->setSingularityDigits(12);
  solver->factorize(A);
  // Exact solution of A x = (2, 2 + eps): x = (1, 1); cond(A) ~ 4e10 bounds the error.
  Eigen::VectorXd x;
  solver->solve(Eigen::Vector2d(2.0, 2.0 + eps), x);
  EXPECT_NEAR(x[0], 1.0, 1e-5);
  EXPECT_NEAR(x[1], 1.0, 1e-5);
  solver->setSingularityDigits(0);
  EXPECT_NO_THROW(solver->factorize(A));
}

TEST_P(EveryMethod, RefusesAnotherPatternWithoutNewAnalysis) {
  auto solver = makeLinearSolver(GetParam());
  solver->analyze(laplacian2d(5));
  EXPECT_THROW(solver->factorize(laplacian2d(6)), Error);
  Triplets t;
  laplacian2d(5, t);
  t.emplace_back(0, 24, 0.5);
  t.emplace_back(24, 0, 0.5);
  EXPECT_THROW(solver->factorize(fromTriplets(25, t)), Error);
  solver->analyze(fromTriplets(25, t));
  EXPECT_NO_THROW(solver->factorize(fromTriplets(25, t)));
}

TEST_P(EveryMethod, ChecksCallOrderAndSizes) {
  auto solver = makeLinearSolver(GetParam());
  Eigen::VectorXd x;
  EXPECT_THROW(solver->factorize(laplacian2d(3)), Error);
  EXPECT_THROW(solver->solve(Eigen::VectorXd::Ones(9), x), Error);
  EXPECT_THROW(solver->analyze(SparseMatrix(3, 4)), Error);
  solver->analyze(laplacian2d(3));
  solver->factorize(laplacian2d(3));
  EXPECT_THROW(solver->solve(Eigen::VectorXd::Ones(8), x), Error);
}

TEST_P(EveryMethod, SolvesTheLaplacianOf200By200) {
  auto solver = makeLinearSolver(GetParam());
  expectSolves(*solver, laplacian2d(200), 1e-9);  // cond ~ 1.6e4
}

INSTANTIATE_TEST_SUITE_P(Methods, EveryMethod, ::testing::ValuesIn(linearSolverMethods()),
                         [](const auto& info) { return info.param; });

class LuMethod : public ::testing::TestWithParam<std::string> {};

TEST_P(LuMethod, SolvesUnsymmetric) {
  auto solver = makeLinearSolver(GetParam());
  expectSolves(*solver, convectionDiffusion(11, 2.5));
}

TEST_P(LuMethod, SolvesSymmetricIndefinite) {
  // Laplacian shifted by -3.3: eigenvalues 0.7 - 2cos(i pi/10) - 2cos(j pi/10), i, j = 1..9,
  // from -3.10 to 4.50, 28 of them negative, the smallest in magnitude 0.0265 (cond ~ 170).
  auto solver = makeLinearSolver(GetParam());
  expectSolves(*solver, laplacian2d(9, -3.3), 1e-9);
}

TEST_P(LuMethod, SolvesSaddlePointWithLagrangeMultipliers) {
  auto solver = makeLinearSolver(GetParam());
  expectSolves(*solver, saddlePoint(10, 5), 1e-9);
}

TEST_P(LuMethod, RowsOfVeryDifferentScalesAreNotSingular) {
  // Rows of scales 1e12 and 1 (a stiffness in Pa next to identity rows, say) that
  // the pivoting swaps: [[1, 1e12], [1, 1]] loses no digit. KLU's audit once read
  // its row scale factors by row where they are by pivot, and found 12 lost.
  const SparseMatrix A = fromTriplets(3, {{0, 0, 1.0}, {0, 1, 1e12}, {1, 0, 1.0}, {1, 1, 1.0}, {2, 2, 1.0}});
  auto solver = makeLinearSolver(GetParam());
  solver->analyze(A);
  ASSERT_NO_THROW(solver->factorize(A));
  Eigen::VectorXd x;
  solver->solve(Eigen::Vector3d(3.0 + 2e12, 5.0, 4.0), x);
  EXPECT_NEAR(x[0], 3.0, 1e-12);
  EXPECT_NEAR(x[1], 2.0, 1e-12);
  EXPECT_NEAR(x[2], 4.0, 1e-12);
  // The saddle point with its stiffness rows and columns times 2.1e11 and its
  // multipliers' over it (the scaling contact uses): solved as at scale 1.
  SparseMatrix B = saddlePoint(10, 5);
  const int n = static_cast<int>(B.rows());
  Eigen::VectorXd d = Eigen::VectorXd::Ones(n);
  d.head(n - 5).setConstant(std::sqrt(2.1e11));
  B = d.asDiagonal() * B * d.asDiagonal();
  auto scaled = makeLinearSolver(GetParam());
  expectSolves(*scaled, B, 1e-7);  // EIGEN_LU does not equilibrate the rows: 2e-8
}

INSTANTIATE_TEST_SUITE_P(Methods, LuMethod, ::testing::Values("UMFPACK", "KLU", "EIGEN_LU"),
                         [](const auto& info) { return info.param; });

TEST(Cholmod, RefusesIndefiniteMatrixNamingTheColumn) {
  auto solver = makeLinearSolver("CHOLMOD");
  // Row and column 20 hold only a negative diagonal: Cholesky fails exactly there, whatever the order.
  Triplets t;
  laplacian2d(6, t);
  Triplets kept;
  for (const auto& e : t)
    if (e.row() != 20 && e.col() != 20) kept.push_back(e);
  kept.emplace_back(20, 20, -4.0);
  const SparseMatrix A = fromTriplets(36, kept);
  solver->analyze(A);
  try {
    solver->factorize(A);
    FAIL() << "CHOLMOD factorized an indefinite matrix";
  } catch (const SingularMatrixError& e) {
    EXPECT_NE(std::string(e.what()).find("not positive definite"), std::string::npos) << e.what();
    EXPECT_EQ(e.column(), 20) << e.what();
  }
}

// Two unknowns per node, as a plane mechanics stiffness (the Laplacian, Kronecker the SPD
// block [2 1; 1 2]): the nested dissection orders the graph of the nodes.
TEST(Cholmod, LargeMatricesAreOrderedByNodes) {
  Triplets laplacian, t;
  laplacian2d(110, laplacian);
  const double block[2][2] = {{2.0, 1.0}, {1.0, 2.0}};
  for (const auto& e : laplacian)
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) t.emplace_back(2 * e.row() + a, 2 * e.col() + b, e.value() * block[a][b]);
  const SparseMatrix A = fromTriplets(2 * 110 * 110, t);
  auto solver = makeLinearSolver("CHOLMOD");
  expectSolves(*solver, A);
  EXPECT_EQ(solver->statistics().ordering, "NESDIS (nodes)");
  // The same ordering every time, so the same bits: METIS keeps its random generator in
  // globals that each call reseeds, so it must not run on two threads at once.
  const Eigen::VectorXd b = A * knownSolution(static_cast<int>(A.rows()));
  Eigen::VectorXd x, again;
  solver->solve(b, x);
  auto second = makeLinearSolver("CHOLMOD");
  second->analyze(A);
  second->factorize(A);
  second->solve(b, again);
  EXPECT_EQ(second->statistics().factorFlops, solver->statistics().factorFlops);
  EXPECT_EQ(x, again);
}

TEST(Cholmod, RefusesSaddlePointButLdltSolvesIt) {
  const SparseMatrix A = saddlePoint(10, 5);
  auto cholesky = makeLinearSolver("CHOLMOD");
  cholesky->analyze(A);
  EXPECT_THROW(cholesky->factorize(A), SingularMatrixError);
  auto ldlt = makeLinearSolver("CHOLMOD_LDLT");
  expectSolves(*ldlt, A, 1e-9);
}

TEST(Cholmod, LdltSolvesSymmetricIndefiniteWithNonzeroDiagonal) {
  auto solver = makeLinearSolver("CHOLMOD_LDLT");
  expectSolves(*solver, laplacian2d(9, -3.3), 1e-9);
}

TEST(Cholmod, RefusesUnsymmetricMatrix) {
  for (const char* method : {"CHOLMOD", "CHOLMOD_LDLT"}) {
    auto solver = makeLinearSolver(method);
    const SparseMatrix A = convectionDiffusion(5, 1.0);
    solver->analyze(A);
    try {
      solver->factorize(A);
      FAIL() << method << " accepted an unsymmetric matrix";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("symmetric"), std::string::npos) << e.what();
    }
  }
}

// Contact as StaticNonlinear assembles it: m x m Laplacian, then `constraints` multipliers
// tying pairs of unknowns. Inactive multipliers are identity rows whose couplings are stored
// zeros (the pattern does not change with the active set); active ones have a zero diagonal,
// or -1/k when penalised.
SparseMatrix contactSystem(int m, int constraints, bool active, double penalty = 0.0) {
  Triplets t;
  laplacian2d(m, t);
  const int n = m * m;
  for (int c = 0; c < constraints; ++c) {
    const int a = (7 * c + 3) % n, b = (13 * c + 11) % n, row = n + c;
    const double on = active ? 1.0 : 0.0;
    for (auto [col, v] : {std::pair{a, on}, std::pair{b, -2.0 * on}}) {
      t.emplace_back(row, col, v);
      t.emplace_back(col, row, v);
    }
    t.emplace_back(row, row, !active ? 1.0 : penalty > 0 ? -1.0 / penalty : 0.0);
  }
  return fromTriplets(n + constraints, t);
}

TEST(MultFront, SolvesASaddlePointWithoutPivoting) {
  MultFrontSolver solver;
  expectSolves(solver, saddlePoint(10, 5), 1e-9);
  EXPECT_EQ(solver.handedOver(), "");
  EXPECT_EQ(solver.statistics().ordering, "CAMD (multipliers last)");
}

// The multipliers are identity rows when the pattern is analysed, and become constraints
// later: named beforehand, they are ordered after the unknowns they tie and every
// factorization is signed.
TEST(MultFront, NamedMultipliersStayLastWhenTheyBecomeActive) {
  for (double penalty : {0.0, 50.0}) {
    MultFrontSolver solver;
    solver.setMultipliersFrom(100);
    const SparseMatrix inactive = contactSystem(10, 5, false), active = contactSystem(10, 5, true, penalty);
    solver.analyze(inactive);
    for (const SparseMatrix* A : {&inactive, &active, &inactive}) {
      const Eigen::VectorXd xKnown = knownSolution(105), b = *A * xKnown;
      solver.factorize(*A);
      Eigen::VectorXd x;
      solver.solve(b, x);
      EXPECT_LT((x - xKnown).norm() / xKnown.norm(), 1e-9) << penalty;
    }
    EXPECT_EQ(solver.handedOver(), "") << penalty;
  }
}

// A large contact system (two unknowns per node, as plane mechanics; multipliers tying
// n . u of a node to that of another, n = (0.6, 0.8)): nested dissection of the nodes, each
// multiplier after the unknowns it ties, and no pivot needs pivoting, whether the
// multipliers are inactive, active or penalised.
constexpr int kLargeNodes = 110 * 110, kLargeUnknowns = 2 * kLargeNodes, kLargeConstraints = 40;
SparseMatrix largeContactSystem(bool active, double penalty) {
  const int m = 110, nodes = kLargeNodes, n = kLargeUnknowns, constraints = kLargeConstraints;
  Triplets laplacian, t;
  laplacian2d(m, laplacian);
  const double block[2][2] = {{2.0, 1.0}, {1.0, 2.0}};
  for (const auto& e : laplacian)
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) t.emplace_back(2 * e.row() + a, 2 * e.col() + b, e.value() * block[a][b]);
  for (int c = 0; c < constraints; ++c) {
    const int slave = 17 * c + 5, master = (nodes - 1) - 29 * c, row = n + c;
    const double on = active ? 1.0 : 0.0;
    for (auto [col, v] : {std::pair{2 * slave, 0.6}, std::pair{2 * slave + 1, 0.8}, std::pair{2 * master, -0.6},
                          std::pair{2 * master + 1, -0.8}}) {
      t.emplace_back(row, col, on * v);
      t.emplace_back(col, row, on * v);
    }
    t.emplace_back(row, row, !active ? 1.0 : penalty > 0 ? -1.0 / penalty : 0.0);
  }
  return fromTriplets(n + constraints, t);
}

TEST(MultFront, LargeContactSystemsAreOrderedByNodesWithTheMultipliersInside) {
  const int n = kLargeUnknowns, constraints = kLargeConstraints;
  const SparseMatrix inactive = largeContactSystem(false, 0.0), active = largeContactSystem(true, 0.0),
                     penalised = largeContactSystem(true, 50.0);
  MultFrontSolver solver;
  solver.setMultipliersFrom(n);
  solver.analyze(inactive);
  EXPECT_EQ(solver.statistics().ordering, "NESDIS (nodes, multipliers after their unknowns)");
  for (const SparseMatrix* A : {&inactive, &active, &penalised, &inactive}) {
    const Eigen::VectorXd xKnown = knownSolution(n + constraints), b = *A * xKnown;
    solver.factorize(*A);
    Eigen::VectorXd x;
    solver.solve(b, x);
    EXPECT_LT((x - xKnown).norm() / xKnown.norm(), 1e-9);
  }
  EXPECT_EQ(solver.handedOver(), "");
  // Factorized only a few times (one linear solve), the same system takes constrained AMD.
  MultFrontSolver once;
  once.setMultipliersFrom(n);
  once.setFactorizationsPerAnalysis(1);
  expectSolves(once, active, 1e-9);
  EXPECT_EQ(once.statistics().ordering, "CAMD (multipliers last)");
}

// Several right-hand sides at once (the factor read once, on the pool's threads) give what
// one solve per column gives, with signed pivots too; so do the small systems, whose
// factorization runs on one thread.
TEST(MultFront, SolveManyGivesTheSolvesOfEachColumn) {
  const SparseMatrix large = largeContactSystem(true, 0.0), small = saddlePoint(10, 5);
  for (const SparseMatrix* A : {&large, &small}) {
    MultFrontSolver solver;
    if (A == &large) solver.setMultipliersFrom(kLargeUnknowns);
    solver.analyze(*A);
    solver.factorize(*A);
    const Eigen::Index n = A->rows();
    Eigen::MatrixXd known(n, 5), X;
    for (int c = 0; c < 5; ++c) known.col(c) = knownSolution(static_cast<int>(n)).array() * (1.0 + c) + c;
    const Eigen::MatrixXd B = *A * known;
    solver.solveMany(B, X);
    ASSERT_EQ(X.cols(), 5);
    for (int c = 0; c < 5; ++c) {
      Eigen::VectorXd x;
      solver.solve(B.col(c), x);
      EXPECT_LT((X.col(c) - x).norm() / x.norm(), 1e-12) << n << " " << c;
      EXPECT_LT((X.col(c) - known.col(c)).norm() / known.col(c).norm(), 1e-9) << n << " " << c;
    }
    EXPECT_EQ(solver.handedOver(), "");
  }
}

// The forward substitution taken during the factorization gives what factorize() then
// solve() give: large (on the pool's threads) and small, with signed pivots; and a matrix
// MULT_FRONT cannot take is handed over to UMFPACK and still solved.
TEST(MultFront, FactorizeAndSolveGivesWhatFactorizeThenSolveGive) {
  const SparseMatrix large = largeContactSystem(true, 0.0), small = saddlePoint(10, 5);
  for (const SparseMatrix* A : {&large, &small}) {
    MultFrontSolver together, apart;
    for (MultFrontSolver* s : {&together, &apart}) {
      if (A == &large) s->setMultipliersFrom(kLargeUnknowns);
      s->analyze(*A);
    }
    const Eigen::VectorXd known = knownSolution(static_cast<int>(A->rows())), b = *A * known;
    Eigen::VectorXd x, y;
    together.factorizeAndSolve(*A, b, x);
    apart.factorize(*A);
    apart.solve(b, y);
    EXPECT_LT((x - y).norm() / y.norm(), 1e-13) << A->rows();
    EXPECT_LT((x - known).norm() / known.norm(), 1e-9) << A->rows();
    Eigen::VectorXd again;  // the factor is whole: a later solve gives the same
    together.solve(b, again);
    EXPECT_LT((again - x).norm() / x.norm(), 1e-13) << A->rows();
    EXPECT_EQ(together.handedOver(), "");
  }
  MultFrontSolver solver;
  const SparseMatrix unsymmetric = convectionDiffusion(5, 1.0);
  const Eigen::VectorXd known = knownSolution(static_cast<int>(unsymmetric.rows())), b = unsymmetric * known;
  solver.analyze(unsymmetric);
  Eigen::VectorXd x;
  solver.factorizeAndSolve(unsymmetric, b, x);
  EXPECT_NE(solver.handedOver(), "");
  EXPECT_LT((x - known).norm() / known.norm(), 1e-10);
}

// Not named, an active multiplier may come before the unknowns it ties: a zero pivot,
// and UMFPACK takes over, once, with the same solution.
TEST(MultFront, ZeroPivotHandsOverToUmfpack) {
  MultFrontSolver solver;
  const SparseMatrix inactive = contactSystem(10, 5, false), active = contactSystem(10, 5, true);
  solver.analyze(inactive);
  solver.factorize(inactive);
  ASSERT_EQ(solver.handedOver(), "");
  const Eigen::VectorXd xKnown = knownSolution(105), b = active * xKnown;
  solver.factorize(active);
  EXPECT_NE(solver.handedOver().find("without pivoting, the matrix is singular"), std::string::npos)
      << solver.handedOver();
  Eigen::VectorXd x;
  solver.solve(b, x);
  EXPECT_LT((x - xKnown).norm() / xKnown.norm(), 1e-9);
  EXPECT_EQ(solver.statistics().factorizeCount, 3);  // the signed attempts and UMFPACK's
}

// An indefinite stiffness (no multiplier): dpotrf stops at a negative pivot, UMFPACK solves.
TEST(MultFront, IndefiniteStiffnessIsHandedToUmfpack) {
  MultFrontSolver solver;
  expectSolves(solver, laplacian2d(9, -3.3), 1e-9);
  EXPECT_NE(solver.handedOver().find("or negative, where no Lagrange multiplier is"), std::string::npos)
      << solver.handedOver();
}

TEST(MultFront, UnsymmetricMatrixIsHandedToUmfpack) {
  MultFrontSolver solver;
  expectSolves(solver, convectionDiffusion(11, 2.5));
  EXPECT_EQ(solver.handedOver(), "the matrix is not symmetric");
}

TEST(Factory, UnknownMethodListsTheAllowedOnes) {
  try {
    makeLinearSolver("PETSC");
    FAIL() << "PETSC is not available";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'PETSC'"), std::string::npos) << what;
    for (const auto& name : linearSolverMethods()) EXPECT_NE(what.find("'" + name + "'"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace aster::linalg
