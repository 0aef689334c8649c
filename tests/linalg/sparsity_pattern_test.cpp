#include "linalg/sparsity_pattern.hpp"

#include <gtest/gtest.h>

#include <string>

#include "test_matrices.hpp"

namespace aster::linalg {
namespace {

using namespace testing;

std::string failureOf(const SymmetryCheck& check, const SparseMatrix& A) {
  try {
    check.require(A, 1e-10, "CHOLMOD");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(SymmetryCheck, AcceptsASymmetricMatrixAndReadsItsDiagonal) {
  const SparseMatrix A = laplacian2d(7, 0.5);
  const SymmetryCheck check(A);
  EXPECT_EQ(failureOf(check, A), "");
  for (int j = 0; j < A.cols(); ++j) EXPECT_EQ(check.diagonal(A, j), 4.5);
}

// When the caller vouches for the symmetry: the diagonal only, and no check to call.
TEST(SymmetryCheck, DiagonalAloneWhenTheSymmetryIsTrusted) {
  const SparseMatrix A = laplacian2d(7, 0.5);
  const SymmetryCheck check(A, false);
  for (int j = 0; j < A.cols(); ++j) EXPECT_EQ(check.diagonal(A, j), 4.5);
  EXPECT_NE(failureOf(check, A).find("internal error"), std::string::npos);
}

TEST(SymmetryCheck, NamesAnUnsymmetricPair) {
  SparseMatrix A = laplacian2d(5);
  const SymmetryCheck check(A);
  A.coeffRef(7, 2) = -1.5;  // A(2,7) = -1
  const std::string what = failureOf(check, A);
  EXPECT_NE(what.find("A(7,2) = -1.5 and A(2,7) = -1"), std::string::npos) << what;
  A.coeffRef(7, 2) = -1.0 + 1e-14;  // round-off: symmetric
  EXPECT_EQ(failureOf(check, A), "");
}

TEST(SymmetryCheck, AnEntryWithoutMirrorMustBeZero) {
  Triplets t;
  laplacian2d(4, t);
  t.emplace_back(0, 15, 0.0);  // stored above the diagonal only
  SparseMatrix A = fromTriplets(16, t);
  const SymmetryCheck check(A);
  EXPECT_EQ(failureOf(check, A), "");
  A.coeffRef(0, 15) = 2.0;
  const std::string what = failureOf(check, A);
  EXPECT_NE(what.find("A(0,15) = 2 and A(15,0) = 0"), std::string::npos) << what;
}

TEST(SymmetryCheck, AgreesWithRequireSymmetricOnUncompressedInput) {
  SparseMatrix A = laplacian2d(4);
  A.coeffRef(3, 0) = 5.0;  // new entry: A is no longer compressed
  ASSERT_FALSE(A.isCompressed());
  const SymmetryCheck check(A);
  EXPECT_NE(failureOf(check, A).find("A(3,0) = 5"), std::string::npos);
}

}  // namespace
}  // namespace aster::linalg

namespace aster::linalg {
namespace {

TEST(SparseMatrix, SymmetrizeValuesKeepsThePattern) {
  // [[4, 1, 0], [3, 5, 2], [0, -6, 7]]: symmetric part [[4, 2, 0], [2, 5, -2], [0, -2, 7]].
  SparseMatrix A(3, 3);
  const std::vector<Eigen::Triplet<double, int>> t = {{0, 0, 4}, {0, 1, 1}, {1, 0, 3}, {1, 1, 5},
                                                     {1, 2, 2}, {2, 1, -6}, {2, 2, 7}};
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  const int nonzeros = static_cast<int>(A.nonZeros());
  symmetrizeValues(A);
  EXPECT_EQ(A.nonZeros(), nonzeros);
  const double expected[3][3] = {{4, 2, 0}, {2, 5, -2}, {0, -2, 7}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_EQ(A.coeff(i, j), expected[i][j]) << i << "," << j;
}

}  // namespace
}  // namespace aster::linalg
