#include "linalg/multifrontal_cholesky.hpp"

#include <cholmod.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include <Eigen/Dense>

#include "linalg/cholmod_views.hpp"
#include "linalg/dense_front.hpp"
#include "test_matrices.hpp"

namespace aster::linalg {
namespace {

using namespace testing;

// CHOLMOD's supernodal analysis of A (lower triangle read) and, as the reference,
// CHOLMOD's own numeric factorization of it.
class CholmodReference {
 public:
  CholmodReference(const SparseMatrix& A, int ordering) {
    cholmod_start(&c_);
    c_.print = 0;
    c_.supernodal = CHOLMOD_SUPERNODAL;
    c_.nmethods = 1;
    c_.method[0].ordering = ordering;
    cholmod_sparse view = lowerView(A);
    L_ = cholmod_analyze(&view, &c_);
    if (!L_) throw Error("analysis failed");
    cholmod_factor* reference = cholmod_copy_factor(L_, &c_);
    cholmod_factorize(&view, reference, &c_);
    referenceMinor_ = reference->minor;
    if (reference->is_super && reference->x) {
      const double* x = static_cast<const double*>(reference->x);
      referenceValues_.assign(x, x + reference->xsize);
    }
    cholmod_free_factor(&reference, &c_);
    structure_ = supernodalStructure(*L_);
  }
  ~CholmodReference() {
    cholmod_free_factor(&L_, &c_);
    cholmod_finish(&c_);
  }
  CholmodReference(const CholmodReference&) = delete;
  CholmodReference& operator=(const CholmodReference&) = delete;

  const SupernodalStructure& structure() const { return structure_; }
  const std::vector<double>& referenceValues() const { return referenceValues_; }
  size_t referenceMinor() const { return referenceMinor_; }
  size_t storage() const { return L_->xsize; }
  int permutation(int k) const { return static_cast<const int*>(L_->Perm)[k]; }

 private:
  cholmod_common c_{};
  cholmod_factor* L_ = nullptr;
  SupernodalStructure structure_;
  std::vector<double> referenceValues_;
  size_t referenceMinor_ = 0;
};

// Largest difference between two factors, relative to the largest entry of the reference.
double relativeDifference(const std::vector<double>& a, const std::vector<double>& reference) {
  double difference = 0, largest = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    difference = std::max(difference, std::abs(a[i] - reference[i]));
    largest = std::max(largest, std::abs(reference[i]));
  }
  return difference / largest;
}

// Two 2D Laplacians side by side, the second scaled: a forest of two elimination trees.
SparseMatrix twoLaplacians(int m) {
  Triplets t;
  laplacian2d(m, t);
  const int n = m * m;
  for (const auto& e : Triplets(t)) t.emplace_back(e.row() + n, e.col() + n, 3.0 * e.value());
  return fromTriplets(2 * n, t);
}

// 7-point Laplacian on an m^3 grid: separators of m^2 unknowns, so the fronts at the top of
// the tree are wider than a panel of the parallel dense factorization.
SparseMatrix laplacian3d(int m) {
  auto id = [m](int i, int j, int k) { return (i * m + j) * m + k; };
  Triplets t;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j)
      for (int k = 0; k < m; ++k) {
        t.emplace_back(id(i, j, k), id(i, j, k), 6.0);
        if (i > 0) t.emplace_back(id(i, j, k), id(i - 1, j, k), -1.0);
        if (i + 1 < m) t.emplace_back(id(i, j, k), id(i + 1, j, k), -1.0);
        if (j > 0) t.emplace_back(id(i, j, k), id(i, j - 1, k), -1.0);
        if (j + 1 < m) t.emplace_back(id(i, j, k), id(i, j + 1, k), -1.0);
        if (k > 0) t.emplace_back(id(i, j, k), id(i, j, k - 1), -1.0);
        if (k + 1 < m) t.emplace_back(id(i, j, k), id(i, j, k + 1), -1.0);
      }
  return fromTriplets(m * m * m, t);
}

struct Case {
  const char* name;
  int ordering;
  int threads;
};

class AgainstCholmod : public ::testing::TestWithParam<Case> {};

// The kernels of the fronts' dense work a test chose, the default's again when it ends.
struct UsingFrontKernels {
  const FrontKernels before = frontKernelsInUse();
  explicit UsingFrontKernels(FrontKernels kernels) { useFrontKernels(kernels); }
  ~UsingFrontKernels() { useFrontKernels(before); }
};

// The factor is CHOLMOD's own (same structure, same arithmetic up to rounding), on one
// thread and planned for 2 or 3 threads (run on the worker pool's), with the fronts' dense
// work by the BLAS and by every build of the dense front kernels this CPU runs.
TEST_P(AgainstCholmod, ComputesCholmodsFactor) {
  const bool parallel = GetParam().threads > 1;
  const SparseMatrix problems[] = {laplacian2d(50), twoLaplacians(30), laplacian3d(18)};
  for (const FrontKernels kernels : {FrontKernels::Blas, FrontKernels::Avx2, FrontKernels::Avx512})
  for (const SparseMatrix& A : problems) {
    if (!frontKernelsRun(kernels)) continue;
    const UsingFrontKernels chosen(kernels);
    SCOPED_TRACE(frontKernelsName(kernels));
    if (GetParam().ordering == CHOLMOD_NATURAL && A.rows() > 5000) continue;  // a band of m^2: dense and slow
    CholmodReference reference(A, GetParam().ordering);
    ASSERT_EQ(reference.referenceMinor(), static_cast<size_t>(A.rows()));
    const MultifrontalCholesky plan(reference.structure(), A, GetParam().threads, 0.0);
    EXPECT_EQ(plan.parallel(), parallel) << A.rows();
    std::vector<double> values(reference.storage(), -7.0);  // garbage the factorization must overwrite
    std::vector<double> pivots(A.rows());
    EXPECT_EQ(plan.factorize(A, values.data(), pivots.data()), -1);
    EXPECT_LT(relativeDifference(values, reference.referenceValues()), 1e-13) << GetParam().name;
    const SupernodalStructure& S = reference.structure();
    for (int s = 0; s < S.supernodeCount; ++s) {
      const int m = S.rowStart[s + 1] - S.rowStart[s];
      for (int k = S.firstColumn[s]; k < S.firstColumn[s + 1]; ++k) {
        const int local = k - S.firstColumn[s];
        EXPECT_EQ(pivots[k], values[S.valueStart[s] + local * (m + 1)]);
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Orderings, AgainstCholmod,
                         ::testing::Values(Case{"AMD", CHOLMOD_AMD, 1}, Case{"NESDIS", CHOLMOD_NESDIS, 1},
                                           Case{"NESDIS2", CHOLMOD_NESDIS, 2}, Case{"AMD2", CHOLMOD_AMD, 2},
                                           Case{"NESDIS3", CHOLMOD_NESDIS, 3},
                                           Case{"NATURAL", CHOLMOD_NATURAL, 2}),
                         [](const auto& info) { return std::string(info.param.name); });

// With the dense front kernels a front gives the same bits whole or cut into pieces for
// several threads, so the factor is the same on one thread as planned for two or three
// (and a front computed whole while other programs hold the pool's other cores changes
// nothing).
TEST(MultifrontalCholesky, FrontKernelsGiveTheSameBitsOnAnyNumberOfThreads) {
  const SparseMatrix A = laplacian3d(18);  // top fronts above kSliceFlops: cut into pieces
  CholmodReference reference(A, CHOLMOD_NESDIS);
  for (const FrontKernels kernels : {FrontKernels::Avx2, FrontKernels::Avx512}) {
    if (!frontKernelsRun(kernels)) continue;
    const UsingFrontKernels chosen(kernels);
    std::vector<double> first;
    for (int threads : {1, 2, 3}) {
      const MultifrontalCholesky plan(reference.structure(), A, threads, 0.0);
      std::vector<double> values(reference.storage());
      ASSERT_EQ(plan.factorize(A, values.data()), -1);
      if (threads == 1)
        first = values;
      else
        EXPECT_EQ(values, first) << frontKernelsName(kernels) << ", " << threads << " threads";
    }
  }
}

// New values on the same pattern: the plan is reused, the factor follows the values.
TEST(MultifrontalCholesky, RefactorizesNewValues) {
  SparseMatrix A = laplacian2d(40);
  CholmodReference first(A, CHOLMOD_NESDIS);
  const MultifrontalCholesky plan(first.structure(), A, 2, 0.0);
  std::vector<double> values(first.storage());
  ASSERT_EQ(plan.factorize(A, values.data()), -1);
  for (int k = 0; k < A.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(A, k); it; ++it)
      if (it.row() == it.col()) it.valueRef() += 0.5 + 0.01 * (k % 5);
  ASSERT_EQ(plan.factorize(A, values.data()), -1);
  CholmodReference second(A, CHOLMOD_NESDIS);  // same ordering: METIS is deterministic
  EXPECT_LT(relativeDifference(values, second.referenceValues()), 1e-13);
}

// A negative pivot: the column reported is the one CHOLMOD reports, serial or in parallel.
TEST(MultifrontalCholesky, ReportsTheColumnOfTheFirstNonPositivePivot) {
  Triplets t;
  laplacian2d(40, t);
  const int bad = 777;
  for (auto& e : t)
    if (e.row() == bad && e.col() == bad) e = Eigen::Triplet<double>(bad, bad, 1.0);  // 1 < 2 + 2 neighbours: indefinite
  const SparseMatrix A = fromTriplets(1600, t);
  CholmodReference reference(A, CHOLMOD_NESDIS);
  ASSERT_LT(reference.referenceMinor(), static_cast<size_t>(A.rows()));
  for (int threads : {1, 2}) {
    const MultifrontalCholesky plan(reference.structure(), A, threads, 0.0);
    std::vector<double> values(reference.storage());
    EXPECT_EQ(plan.factorize(A, values.data()), static_cast<int>(reference.referenceMinor())) << threads;
  }
}

// The same in the widest front, the root, whose dense work is split between threads: a
// negative diagonal on the last pivot fails there and nowhere before.
TEST(MultifrontalCholesky, ReportsANonPositivePivotInTheRootFront) {
  SparseMatrix A = laplacian3d(16);
  const int last = CholmodReference(A, CHOLMOD_NESDIS).permutation(static_cast<int>(A.rows()) - 1);
  A.coeffRef(last, last) = -1.0;
  CholmodReference reference(A, CHOLMOD_NESDIS);
  ASSERT_EQ(reference.referenceMinor(), static_cast<size_t>(A.rows() - 1));
  const MultifrontalCholesky plan(reference.structure(), A, 2, 0.0);
  std::vector<double> values(reference.storage());
  EXPECT_EQ(plan.factorize(A, values.data()), A.rows() - 1);
}

// L S L^T from the supernodal storage, dense.
Eigen::MatrixXd signedProduct(const SupernodalStructure& S, const std::vector<double>& values,
                              const std::vector<double>& pivots) {
  Eigen::MatrixXd L = Eigen::MatrixXd::Zero(S.n, S.n);
  for (int s = 0; s < S.supernodeCount; ++s) {
    const int m = S.rowStart[s + 1] - S.rowStart[s];
    for (int k = S.firstColumn[s]; k < S.firstColumn[s + 1]; ++k)
      for (int i = 0; i < m; ++i)
        L(S.rows[S.rowStart[s] + i], k) = values[S.valueStart[s] + i + static_cast<size_t>(k - S.firstColumn[s]) * m];
  }
  Eigen::VectorXd sign(S.n);
  for (int k = 0; k < S.n; ++k) sign[k] = pivots[k] < 0 ? -1.0 : 1.0;
  return L * sign.asDiagonal() * L.transpose();
}

// Stiffness + Lagrange multipliers, the multipliers last: L S L^T reproduces A, with one
// negative pivot per multiplier (the inertia of [K B^T; B 0], K positive definite, B of full rank).
TEST(MultifrontalCholesky, SignedPivotsFactorASaddlePoint) {
  const int m = 10, constraints = 5, n = m * m + constraints;
  const SparseMatrix A = saddlePoint(m, constraints);
  CholmodReference reference(A, CHOLMOD_NATURAL);
  std::vector<char> indefinite(n, 0);  // in the order of L (CHOLMOD may postorder the natural one)
  Eigen::MatrixXd PAPt(n, n);
  const Eigen::MatrixXd dense(A);
  for (int k = 0; k < n; ++k) {
    indefinite[k] = reference.permutation(k) >= m * m;
    for (int l = 0; l < n; ++l) PAPt(k, l) = dense(reference.permutation(k), reference.permutation(l));
  }
  for (int threads : {1, 2}) {
    const MultifrontalCholesky plan(reference.structure(), A, threads, 0.0, indefinite);
    std::vector<double> values(reference.storage()), pivots(n);
    ASSERT_EQ(plan.factorize(A, values.data(), pivots.data()), -1) << threads;
    EXPECT_EQ(std::count_if(pivots.begin(), pivots.end(), [](double p) { return p < 0; }), constraints);
    for (int k = 0; k < n; ++k) EXPECT_EQ(pivots[k] < 0, indefinite[k] == 1) << k;
    const Eigen::MatrixXd product = signedProduct(reference.structure(), values, pivots);
    EXPECT_LT((product - PAPt).cwiseAbs().maxCoeff(), 1e-13) << threads;
  }
}

// A front wider than a panel of the signed factorization (48 columns), its multipliers
// inside it: a dense [K1 B^T C; B 0 0; C^T 0 K2], K = [K1 C; C^T K2] = G G^T + n I
// positive definite, B (40 x 100) of full rank acting on K1's unknowns only, every entry
// non-zero (one supernode of 190 columns), in that order: K1's 100 columns, the 40
// multipliers, K2's 50 (the Schur complement of K2 stays positive definite). L S L^T
// reproduces A to round-off and the signs are the inertia: - for the multipliers only.
TEST(MultifrontalCholesky, SignedPanelsFactorAWideSaddlePointFront) {
  const int nk = 150, n1 = 100, nc = 40, n = nk + nc;
  Eigen::MatrixXd G(nk, nk), B(nc, n1);
  for (int i = 0; i < nk; ++i)
    for (int j = 0; j < nk; ++j) G(i, j) = std::sin(1.0 + i + 3.0 * j);
  for (int i = 0; i < nc; ++i)
    for (int j = 0; j < n1; ++j) B(i, j) = std::cos(2.0 + 5.0 * i + j) + (i == j ? 4.0 : 0.0);
  const Eigen::MatrixXd K = G * G.transpose() + nk * Eigen::MatrixXd::Identity(nk, nk);
  // Rows and columns: K1 (0 .. 99), the multipliers (100 .. 139), K2 (140 .. 189).
  auto at = [&](int k) { return k < n1 ? k : k < n1 + nc ? -1 : k - nc; };  // index in K, -1: a multiplier
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      if (at(i) >= 0 && at(j) >= 0) dense(i, j) = K(at(i), at(j));
      else if (at(i) < 0 && at(j) >= 0 && at(j) < n1) dense(i, j) = B(i - n1, at(j));
      else if (at(j) < 0 && at(i) >= 0 && at(i) < n1) dense(i, j) = B(j - n1, at(i));
    }
  Triplets t;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) t.emplace_back(i, j, dense(i, j));  // the zeros stored too: one dense front
  const SparseMatrix A = fromTriplets(n, t);
  CholmodReference reference(A, CHOLMOD_NATURAL);
  std::vector<char> indefinite(n, 0);
  Eigen::MatrixXd PAPt(n, n);
  for (int k = 0; k < n; ++k) {
    indefinite[k] = at(reference.permutation(k)) < 0;
    for (int l = 0; l < n; ++l) PAPt(k, l) = dense(reference.permutation(k), reference.permutation(l));
  }
  for (int threads : {1, 2}) {
    const MultifrontalCholesky plan(reference.structure(), A, threads, 0.0, indefinite);
    std::vector<double> values(reference.storage()), pivots(n);
    ASSERT_EQ(plan.factorize(A, values.data(), pivots.data()), -1) << threads;
    for (int k = 0; k < n; ++k) EXPECT_EQ(pivots[k] < 0, indefinite[k] == 1) << k;
    const Eigen::MatrixXd product = signedProduct(reference.structure(), values, pivots);
    EXPECT_LT((product - PAPt).cwiseAbs().maxCoeff(), 1e-12 * PAPt.cwiseAbs().maxCoeff()) << threads;
  }
}

// The solves with the factor: P A P^T w = P b solved in place, checked by the residual
// of A x = b (relative to |A| |x|, round-off times a few hundred), for a forest of two
// trees and a 3D Laplacian planned for one to three threads, and for a saddle point
// (signed pivots, S between the two triangular solves).
double relativeResidual(const SparseMatrix& A, const Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  const Eigen::VectorXd r = A * x - b;
  const SparseMatrix absA = A.cwiseAbs();
  const Eigen::VectorXd scale = absA * x.cwiseAbs() + b.cwiseAbs();
  return (r.cwiseAbs().array() / scale.array()).maxCoeff();
}

Eigen::VectorXd solveWith(const MultifrontalCholesky& plan, const CholmodReference& reference,
                          const std::vector<double>& values, const double* pivots, const Eigen::VectorXd& b) {
  const int n = static_cast<int>(b.size());
  std::vector<double> y(n);
  for (int k = 0; k < n; ++k) y[k] = b(reference.permutation(k));
  plan.solve(values.data(), pivots, y.data());
  Eigen::VectorXd x(n);
  for (int k = 0; k < n; ++k) x(reference.permutation(k)) = y[k];
  return x;
}

TEST(MultifrontalCholesky, SolvesWithTheFactorOnAnyNumberOfThreads) {
  for (const SparseMatrix& A : {twoLaplacians(40), laplacian3d(16)}) {
    CholmodReference reference(A, CHOLMOD_NESDIS);
    Eigen::VectorXd b(A.rows());
    for (int i = 0; i < b.size(); ++i) b(i) = std::sin(0.3 * i) + 0.5;
    Eigen::VectorXd first;
    for (int threads : {1, 2, 3}) {
      const MultifrontalCholesky plan(reference.structure(), A, threads, 0.0);
      std::vector<double> values(reference.storage());
      ASSERT_EQ(plan.factorize(A, values.data()), -1);
      const Eigen::VectorXd x = solveWith(plan, reference, values, nullptr, b);
      EXPECT_LT(relativeResidual(A, x, b), 1e-13) << threads;
      if (threads == 1) first = x;
      EXPECT_LT((x - first).cwiseAbs().maxCoeff(), 1e-12 * first.cwiseAbs().maxCoeff()) << threads;
    }
  }
}

TEST(MultifrontalCholesky, SolvesASaddlePointWithSignedPivots) {
  const int m = 12, constraints = 6, n = m * m + constraints;
  const SparseMatrix A = saddlePoint(m, constraints);
  CholmodReference reference(A, CHOLMOD_NATURAL);
  std::vector<char> indefinite(n, 0);
  for (int k = 0; k < n; ++k) indefinite[k] = reference.permutation(k) >= m * m;
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i) b(i) = std::cos(0.7 * i);
  for (int threads : {1, 2}) {
    const MultifrontalCholesky plan(reference.structure(), A, threads, 0.0, indefinite);
    std::vector<double> values(reference.storage()), pivots(n);
    ASSERT_EQ(plan.factorize(A, values.data(), pivots.data()), -1);
    const Eigen::VectorXd x = solveWith(plan, reference, values, pivots.data(), b);
    EXPECT_LT(relativeResidual(A, x, b), 1e-12) << threads;
  }
}

// A positive definite matrix through signed fronts only: CHOLMOD's factor, all signs +.
TEST(MultifrontalCholesky, SignedFrontsOfAPositiveDefiniteMatrixGiveCholesky) {
  const SparseMatrix A = laplacian2d(30);
  CholmodReference reference(A, CHOLMOD_AMD);
  const MultifrontalCholesky plan(reference.structure(), A, 1, 0.0, std::vector<char>(A.rows(), 1));
  std::vector<double> values(reference.storage()), pivots(A.rows());
  ASSERT_EQ(plan.factorize(A, values.data(), pivots.data()), -1);
  EXPECT_LT(relativeDifference(values, reference.referenceValues()), 1e-13);
  EXPECT_GT(*std::min_element(pivots.begin(), pivots.end()), 0.0);
}

// A multiplier met before the unknowns it constrains has a zero pivot: reported.
TEST(MultifrontalCholesky, SignedFrontsReportAZeroPivot) {
  Triplets t{{0, 0, 0.0}, {0, 1, 1.0}, {1, 0, 1.0}, {1, 1, 2.0}};
  const SparseMatrix A = fromTriplets(2, t);
  CholmodReference reference(A, CHOLMOD_NATURAL);
  const MultifrontalCholesky plan(reference.structure(), A, 1, 0.0, {1, 1});
  std::vector<double> values(reference.storage());
  EXPECT_EQ(plan.factorize(A, values.data()), 0);
}

// Small problems stay on the calling thread.
TEST(MultifrontalCholesky, SmallProblemsRunOnOneThread) {
  const SparseMatrix A = laplacian2d(20);
  CholmodReference reference(A, CHOLMOD_AMD);
  const MultifrontalCholesky plan(reference.structure(), A, 2);
  EXPECT_LT(plan.estimatedFlops(), MultifrontalCholesky::kParallelFlops);
  EXPECT_FALSE(plan.parallel());
}

TEST(MultifrontalCholesky, RefusesAMatrixOfAnotherSize) {
  const SparseMatrix A = laplacian2d(10);
  CholmodReference reference(A, CHOLMOD_AMD);
  EXPECT_THROW(MultifrontalCholesky(reference.structure(), laplacian2d(11), 1), Error);
}

}  // namespace
}  // namespace aster::linalg
