// Load kernels: dead tractions and body forces against closed-form integrals;
// follower pressure against its geometric meaning and its stiffness against
// central differences.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mechanics/loads.hpp"

using namespace aster;
using namespace aster::mechanics;

TEST(Loads, DeadTractionOnSeg3IntegratesPolynomials) {
  // Straight SEG3 from (0,0) to (2,0), middle (1,0): X = 1 + xi, ds = dxi.
  fem::EdgeCoords<CellType::SEG3> X;
  X << 0, 0, 2, 0, 1, 0;
  const auto f = deadEdgeTraction<CellType::SEG3>(X, [](const Eigen::Vector2d& p) {
    return Eigen::Vector2d(p(0) * p(0), 1.0);
  });
  // Resultant: int_0^2 x^2 dx = 8/3; int_0^2 1 = 2. Moment about 0: int x^3 = 4.
  EXPECT_NEAR(f(0) + f(2) + f(4), 8.0 / 3, 1e-14);
  EXPECT_NEAR(f(1) + f(3) + f(5), 2.0, 1e-14);
  // Consistent nodal forces of a constant traction on SEG3: 1/6, 1/6, 2/3 of the total.
  EXPECT_NEAR(f(1), 2.0 / 6, 1e-14);
  EXPECT_NEAR(f(5), 2.0 * 2 / 3, 1e-14);
  // Node 2 (x=2) gets int N_2 x^2 dx with N_2 = x(x-1)/2 on [0,2]: int (x^4 - x^3)/2 = (32/5 - 4)/2 = 1.2.
  EXPECT_NEAR(f(2), 1.2, 1e-14);
}

TEST(Loads, DeadTractionOnSlantedSeg2UsesReferenceLength) {
  fem::EdgeCoords<CellType::SEG2> X;
  X << 0, 0, 3, 4;  // length 5
  const auto f = deadEdgeTraction<CellType::SEG2>(X, [](const Eigen::Vector2d&) { return Eigen::Vector2d(1, -2); });
  EXPECT_NEAR(f(0), 2.5, 1e-14);
  EXPECT_NEAR(f(3), -5.0, 1e-14);
}

TEST(Loads, BodyForceIntegratesOverTheCell) {
  // QUAD8 on [0,2] x [0,1], straight edges; b = (x y, 1).
  fem::NodeCoords<CellType::QUAD8> X;
  X << 0, 0, 2, 0, 2, 1, 0, 1, 1, 0, 2, 0.5, 1, 1, 0, 0.5;
  const auto f = bodyForce<CellType::QUAD8>(X, [](const Eigen::Vector2d& p) { return Eigen::Vector2d(p(0) * p(1), 1.0); });
  double fx = 0, fy = 0;
  for (int a = 0; a < 8; ++a) {
    fx += f(2 * a);
    fy += f(2 * a + 1);
  }
  EXPECT_NEAR(fx, 1.0, 1e-14);  // int x y = 2 * 0.5
  EXPECT_NEAR(fy, 2.0, 1e-14);
  // TRIA6 (0,0),(1,0),(0,1): int x^2 = 1/12.
  fem::NodeCoords<CellType::TRIA6> T;
  T << 0, 0, 1, 0, 0, 1, 0.5, 0, 0.5, 0.5, 0, 0.5;
  const auto g = bodyForce<CellType::TRIA6>(T, [](const Eigen::Vector2d& p) { return Eigen::Vector2d(p(0) * p(0), 0); });
  EXPECT_NEAR(g(0) + g(2) + g(4) + g(6) + g(8) + g(10), 1.0 / 12, 1e-15);
}

TEST(Loads, FollowerPressureActsOnTheDeformedEdge) {
  // Bottom edge (0,0)->(1,0) of a body above, rotated rigidly by 90 degrees and
  // stretched by 2: constant p gives -p n_current * current length.
  fem::EdgeCoords<CellType::SEG2> X;
  X << 0, 0, 1, 0;
  EdgeVector<CellType::SEG2> u;
  u << 0, 0, -1, 2;  // node 2 at (0, 2): the edge now points along +y, length 2
  EdgeVector<CellType::SEG2> f;
  followerPressure<CellType::SEG2>(X, u, [](const Eigen::Vector2d&) { return 3.0; }, &f, nullptr);
  // Current normal (dy, -dx)/|.| = (1, 0); force = -3 * (1,0) * 2 = (-6, 0).
  EXPECT_NEAR(f(0) + f(2), -6.0, 1e-14);
  EXPECT_NEAR(f(1) + f(3), 0.0, 1e-14);
}

template <CellType T>
void pressureStiffness() {
  SCOPED_TRACE(fem::cellName(T));
  constexpr int n = fem::Cell<T>::nodes;
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> uni(-1, 1);
  fem::EdgeCoords<T> X;
  X.row(0) << 0.0, 0.1;
  X.row(1) << 1.0, -0.1;
  if (n == 3) X.row(2) << 0.5, 0.15;
  auto p = [](const Eigen::Vector2d& x) { return 2.0 + x(0) * x(0) - x(1); };
  for (int trial = 0; trial < 3; ++trial) {
    EdgeVector<T> u, f, fp, fm;
    for (int i = 0; i < 2 * n; ++i) u(i) = 0.2 * uni(rng);
    EdgeMatrix<T> K, Kfd;
    followerPressure<T>(X, u, p, &f, &K);
    const double h = 1e-6;
    for (int j = 0; j < 2 * n; ++j) {
      EdgeVector<T> up = u, um = u;
      up(j) += h;
      um(j) -= h;
      followerPressure<T>(X, up, p, &fp, nullptr);
      followerPressure<T>(X, um, p, &fm, nullptr);
      Kfd.col(j) = (fp - fm) / (2 * h);
    }
    EXPECT_LT((K - Kfd).norm(), 1e-8 * K.norm());
  }
}

TEST(Loads, FollowerPressureStiffnessMatchesDifferences) {
  pressureStiffness<CellType::SEG2>();
  pressureStiffness<CellType::SEG3>();
}

// A pressure of the current point x = X + u (code_aster's XF, YF) adds dp/dx N_b to the tangent.
template <CellType T>
void currentPointPressureStiffness(bool axisymmetric) {
  SCOPED_TRACE(fem::cellName(T));
  constexpr int n = fem::Cell<T>::nodes;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uni(-1, 1);
  fem::EdgeCoords<T> X;
  X.row(0) << 1.0, 0.1;
  X.row(1) << 2.0, -0.1;
  if (n == 3) X.row(2) << 1.5, 0.15;
  auto p = [](const Eigen::Vector2d& ref, const Eigen::Vector2d& x, Eigen::Vector2d* dpdx) {
    *dpdx << 2.0 * x(0) * x(1) + ref(1), x(0) * x(0);
    return 2.0 + x(0) * x(0) * x(1) + ref(1) * x(0);
  };
  for (int trial = 0; trial < 3; ++trial) {
    EdgeVector<T> u, f, fp, fm;
    for (int i = 0; i < 2 * n; ++i) u(i) = 0.2 * uni(rng);
    EdgeMatrix<T> K, Kfd;
    followerPressure<T>(X, u, p, &f, &K, axisymmetric);
    const double h = 1e-6;
    for (int j = 0; j < 2 * n; ++j) {
      EdgeVector<T> up = u, um = u;
      up(j) += h;
      um(j) -= h;
      followerPressure<T>(X, up, p, &fp, nullptr, axisymmetric);
      followerPressure<T>(X, um, p, &fm, nullptr, axisymmetric);
      Kfd.col(j) = (fp - fm) / (2 * h);
    }
    EXPECT_LT((K - Kfd).norm(), 1e-8 * K.norm());
  }
}

TEST(Loads, PressureOfTheCurrentPointStiffnessMatchesDifferences) {
  for (bool axis : {false, true}) {
    currentPointPressureStiffness<CellType::SEG2>(axis);
    currentPointPressureStiffness<CellType::SEG3>(axis);
  }
}
