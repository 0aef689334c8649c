// Shape functions: partition of unity, Kronecker property at the nodes,
// reproduction of linear fields, derivatives against central differences.
#include <gtest/gtest.h>

#include <random>

#include "fem/shape_functions.hpp"

using namespace aster::fem;

namespace {

template <CellType T>
typename Cell<T>::Point randomPoint(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1), v(0, 1);
  typename Cell<T>::Point p;
  if constexpr (T == CellType::TRIA3 || T == CellType::TRIA6) {
    double a = v(rng), b = v(rng);
    if (a + b > 1) { a = 1 - a; b = 1 - b; }
    p << a, b;
  } else {
    for (int i = 0; i < Cell<T>::dim; ++i) p(i) = u(rng);
  }
  return p;
}

template <CellType T>
void checkCell() {
  using C = Cell<T>;
  SCOPED_TRACE(cellName(T));
  const auto nodes = C::referenceNodes();
  // Kronecker: N_a(x_b) = delta_ab.
  for (int b = 0; b < C::nodes; ++b) {
    const typename C::Point p = nodes.row(b).transpose();
    const auto N = C::values(p);
    for (int a = 0; a < C::nodes; ++a) EXPECT_NEAR(N(a), a == b ? 1.0 : 0.0, 1e-15) << "a=" << a << " b=" << b;
  }
  std::mt19937 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    const auto p = randomPoint<T>(rng);
    const auto N = C::values(p);
    const auto G = C::gradients(p);
    EXPECT_NEAR(N.sum(), 1.0, 1e-14);                       // partition of unity
    EXPECT_NEAR(G.colwise().sum().norm(), 0.0, 1e-14);      // its derivative
    // Linear reproduction: sum N_a x_a = x, sum dN_a x_a^T = I.
    EXPECT_NEAR((nodes.transpose() * N - p).norm(), 0.0, 1e-14);
    const auto I = (nodes.transpose() * G).eval();
    EXPECT_NEAR((I - decltype(I)::Identity()).norm(), 0.0, 1e-14);
    // Derivatives against central differences (step h: error O(h^2) * third derivative = 0 for quadratics).
    const double h = 1e-5;
    for (int j = 0; j < C::dim; ++j) {
      auto pp = p, pm = p;
      pp(j) += h;
      pm(j) -= h;
      const auto fd = ((C::values(pp) - C::values(pm)) / (2 * h)).eval();
      EXPECT_NEAR((fd - G.col(j)).norm(), 0.0, 1e-9) << "direction " << j;
    }
  }
}

}  // namespace

TEST(ShapeFunctions, Seg2) { checkCell<CellType::SEG2>(); }
TEST(ShapeFunctions, Seg3) { checkCell<CellType::SEG3>(); }
TEST(ShapeFunctions, Tria3) { checkCell<CellType::TRIA3>(); }
TEST(ShapeFunctions, Tria6) { checkCell<CellType::TRIA6>(); }
TEST(ShapeFunctions, Quad4) { checkCell<CellType::QUAD4>(); }
TEST(ShapeFunctions, Quad8) { checkCell<CellType::QUAD8>(); }
TEST(ShapeFunctions, Quad9) { checkCell<CellType::QUAD9>(); }

TEST(ShapeFunctions, SegmentSecondDerivativesMatchDifferences) {
  const double h = 1e-4;
  for (double s : {-0.7, 0.0, 0.3}) {
    using C = Cell<CellType::SEG3>;
    const auto fd = ((C::gradients(C::Point(s + h)) - C::gradients(C::Point(s - h))) / (2 * h)).eval();
    EXPECT_NEAR((fd - C::secondDerivatives(C::Point(s))).norm(), 0.0, 1e-10);
    using L = Cell<CellType::SEG2>;
    EXPECT_EQ(L::secondDerivatives(L::Point(s)).norm(), 0.0);
  }
}

// Quadratic cells reproduce quadratic fields exactly: interpolate x^2 y (QUAD9
// only: it is in Q2) and x*y, x^2, y^2 (all quadratic cells).
TEST(ShapeFunctions, QuadraticCellsReproduceQuadratics) {
  auto check = [](auto tag) {
    constexpr CellType T = decltype(tag)::value;
    using C = Cell<T>;
    const auto X = C::referenceNodes();
    typename C::Point p;
    p << 0.21, 0.33;
    auto f = [](double x, double y) { return 1 + 2 * x - y + 3 * x * y - x * x + 0.5 * y * y; };
    typename C::Values nodal;
    for (int a = 0; a < C::nodes; ++a) nodal(a) = f(X(a, 0), X(a, 1));
    EXPECT_NEAR(C::values(p).dot(nodal), f(p(0), p(1)), 1e-14) << cellName(T);
  };
  check(CellTag<CellType::TRIA6>{});
  check(CellTag<CellType::QUAD8>{});
  check(CellTag<CellType::QUAD9>{});
  using C = Cell<CellType::QUAD9>;
  const auto X = C::referenceNodes();
  C::Values nodal;
  for (int a = 0; a < 9; ++a) nodal(a) = X(a, 0) * X(a, 0) * X(a, 1) * X(a, 1);
  EXPECT_NEAR(C::values(C::Point(0.4, -0.6)).dot(nodal), 0.16 * 0.36, 1e-14);
}
