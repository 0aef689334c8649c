// Quadrature exactness on monomials against closed-form integrals:
//   int_{-1}^{1} x^k = 2/(k+1) for k even, 0 for k odd;
//   int_triangle x^i y^j = i! j! / (i+j+2)!.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "fem/quadrature.hpp"

using namespace aster::fem;

namespace {
double lineMonomial(int k) { return k % 2 ? 0.0 : 2.0 / (k + 1); }
double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }
double triangleMonomial(int i, int j) { return factorial(i) * factorial(j) / factorial(i + j + 2); }
}  // namespace

TEST(Quadrature, GaussLegendreExactToDegree2nMinus1) {
  for (int n = 1; n <= kMaxGaussPoints; ++n) {
    const auto& r = gaussLegendre(n);
    ASSERT_EQ(r.size(), n);
    EXPECT_EQ(r.degree, 2 * n - 1);
    for (int k = 0; k <= 2 * n - 1; ++k) {
      double s = 0;
      for (int q = 0; q < n; ++q) s += r.weights[q] * std::pow(r.points[q](0), k);
      EXPECT_NEAR(s, lineMonomial(k), 1e-14) << "n=" << n << " k=" << k;
    }
    // ... and not beyond (x^(2n) is not integrated exactly).
    double s = 0;
    for (int q = 0; q < n; ++q) s += r.weights[q] * std::pow(r.points[q](0), 2 * n);
    EXPECT_GT(std::abs(s - lineMonomial(2 * n)), 1e-9) << "n=" << n;
  }
}

TEST(Quadrature, KnownGaussPoints) {
  EXPECT_NEAR(gaussLegendre(2).points[1](0), 1 / std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(gaussLegendre(3).points[2](0), std::sqrt(0.6), 1e-15);
  EXPECT_NEAR(gaussLegendre(3).weights[1], 8.0 / 9, 1e-15);
  EXPECT_NEAR(gaussLegendre(5).weights[2], 128.0 / 225, 1e-15);
}

TEST(Quadrature, QuadrangleTensorRules) {
  for (int n = 1; n <= 5; ++n) {
    const auto& r = gaussQuadrangle(n);
    ASSERT_EQ(r.size(), n * n);
    for (int i = 0; i <= 2 * n - 1; ++i)
      for (int j = 0; j <= 2 * n - 1; ++j) {
        double s = 0;
        for (int q = 0; q < r.size(); ++q)
          s += r.weights[q] * std::pow(r.points[q](0), i) * std::pow(r.points[q](1), j);
        EXPECT_NEAR(s, lineMonomial(i) * lineMonomial(j), 1e-14) << n << " " << i << " " << j;
      }
  }
}

TEST(Quadrature, TriangleRulesExactToTheirDegree) {
  const int expectedPoints[] = {0, 1, 3, 6, 6, 7, 12};
  for (int d = 1; d <= kMaxTriangleDegree; ++d) {
    const auto& r = gaussTriangle(d);
    EXPECT_EQ(r.size(), expectedPoints[d]);
    EXPECT_GE(r.degree, d);
    for (int q = 0; q < r.size(); ++q) {
      EXPECT_GT(r.weights[q], 0);
      EXPECT_GT(r.points[q](0), 0);
      EXPECT_GT(r.points[q](1), 0);
      EXPECT_LT(r.points[q](0) + r.points[q](1), 1);
    }
    for (int i = 0; i <= r.degree; ++i)
      for (int j = 0; i + j <= r.degree; ++j) {
        double s = 0;
        for (int q = 0; q < r.size(); ++q)
          s += r.weights[q] * std::pow(r.points[q](0), i) * std::pow(r.points[q](1), j);
        EXPECT_NEAR(s, triangleMonomial(i, j), 1e-14) << "degree " << d << ": x^" << i << " y^" << j;
      }
  }
}

TEST(Quadrature, DefaultRulesAndErrors) {
  EXPECT_EQ(fullSurfaceRule(CellType::TRIA3).size(), 1);
  EXPECT_EQ(fullSurfaceRule(CellType::TRIA6).size(), 6);
  EXPECT_EQ(fullSurfaceRule(CellType::QUAD4).size(), 4);
  EXPECT_EQ(fullSurfaceRule(CellType::QUAD8).size(), 9);
  EXPECT_EQ(fullSurfaceRule(CellType::QUAD9).size(), 9);
  EXPECT_EQ(fullEdgeRule(CellType::SEG3).size(), 3);
  EXPECT_EQ(edgeRule(7).size(), 4);
  EXPECT_GE(surfaceRule(CellType::QUAD8, 6).degree, 6);
  EXPECT_THROW(gaussTriangle(7), aster::Error);
  EXPECT_THROW(gaussLegendre(0), aster::Error);
  EXPECT_THROW(fullSurfaceRule(CellType::SEG2), aster::Error);
  EXPECT_THROW(fullEdgeRule(CellType::QUAD4), aster::Error);
}
