// Quadrature exactness on monomials against closed-form integrals:
//   int_{-1}^{1} x^k = 2/(k+1) for k even, 0 for k odd;
//   int_triangle x^i y^j = i! j! / (i+j+2)!.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

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
  EXPECT_EQ(edgeRule(7).size(), 4);
  EXPECT_GE(surfaceRule(CellType::QUAD8, 6).degree, 6);
  EXPECT_THROW(gaussTriangle(7), aster::Error);
  EXPECT_THROW(gaussLegendre(0), aster::Error);
  EXPECT_THROW(fullSurfaceRule(CellType::SEG2, false), aster::Error);
  EXPECT_THROW(fullEdgeRule(CellType::QUAD4), aster::Error);
}

// The element rules are code_aster's RIGI families of its plane mechanical
// elements (catalogue: TRIA3 FPG1, TRIA6 FPG3 (FPG6 in AXIS), QUAD4 FPG4,
// QUAD8/QUAD9 FPG9; edge cells SE2 FPG2, SE3 FPG3), point by point in its order
// (code_aster's reference manual R3.01.01), with the coordinates typed from
// their formulas.
namespace {

struct Row {
  double x, y, w;
};

void expectTable(const QuadratureRule<2>& r, const std::vector<Row>& rows, const char* what) {
  ASSERT_EQ(r.size(), static_cast<int>(rows.size())) << what;
  for (std::size_t q = 0; q < rows.size(); ++q) {
    EXPECT_NEAR(r.points[q](0), rows[q].x, 1e-15) << what << " point " << q + 1;
    EXPECT_NEAR(r.points[q](1), rows[q].y, 1e-15) << what << " point " << q + 1;
    EXPECT_NEAR(r.weights[q], rows[q].w, 1e-15) << what << " point " << q + 1;
  }
}

// Largest total degree d such that every monomial x^i y^j, i + j <= d, is exact.
int exactDegree(const QuadratureRule<2>& r, bool triangle) {
  for (int d = 0; d <= 12; ++d)
    for (int i = 0; i <= d; ++i) {
      const int j = d - i;
      double s = 0;
      for (int q = 0; q < r.size(); ++q) s += r.weights[q] * std::pow(r.points[q](0), i) * std::pow(r.points[q](1), j);
      const double exact = triangle ? triangleMonomial(i, j) : lineMonomial(i) * lineMonomial(j);
      if (std::abs(s - exact) > 1e-13) return d - 1;
    }
  return 12;
}

int exactDegree(const QuadratureRule<1>& r) {
  for (int k = 0; k <= 20; ++k) {
    double s = 0;
    for (int q = 0; q < r.size(); ++q) s += r.weights[q] * std::pow(r.points[q](0), k);
    if (std::abs(s - lineMonomial(k)) > 1e-13) return k - 1;
  }
  return 20;
}

}  // namespace

TEST(Quadrature, Tria3IsFpg1) {
  for (bool axis : {false, true}) {
    const auto& r = fullSurfaceRule(CellType::TRIA3, axis);
    expectTable(r, {{1.0 / 3, 1.0 / 3, 0.5}}, "TRIA3 FPG1");
    EXPECT_EQ(exactDegree(r, true), 1);
    EXPECT_EQ(r.degree, 1);
  }
}

TEST(Quadrature, Tria6IsFpg3InPlaneModels) {
  const auto& r = fullSurfaceRule(CellType::TRIA6, false);
  expectTable(r, {{1.0 / 6, 1.0 / 6, 1.0 / 6}, {2.0 / 3, 1.0 / 6, 1.0 / 6}, {1.0 / 6, 2.0 / 3, 1.0 / 6}},
              "TRIA6 FPG3");
  EXPECT_EQ(exactDegree(r, true), 2);
  EXPECT_EQ(r.degree, 2);
}

TEST(Quadrature, Tria6IsFpg6InAxis) {
  const double a = 0.445948490915965, b = 0.091576213509771;
  const double p1 = 0.111690794839005, p2 = 0.054975871827661;
  const auto& r = fullSurfaceRule(CellType::TRIA6, true);
  expectTable(r,
              {{b, b, p2}, {1 - 2 * b, b, p2}, {b, 1 - 2 * b, p2}, {a, 1 - 2 * a, p1}, {a, a, p1}, {1 - 2 * a, a, p1}},
              "TRIA6 FPG6");
  EXPECT_EQ(exactDegree(r, true), 4);
  EXPECT_EQ(r.degree, 4);
}

TEST(Quadrature, Quad4IsFpg4Counterclockwise) {
  const double a = 1 / std::sqrt(3.0);
  for (bool axis : {false, true}) {
    const auto& r = fullSurfaceRule(CellType::QUAD4, axis);
    expectTable(r, {{-a, -a, 1}, {a, -a, 1}, {a, a, 1}, {-a, a, 1}}, "QUAD4 FPG4");
    EXPECT_EQ(exactDegree(r, false), 3);
    EXPECT_EQ(r.degree, 3);
  }
}

TEST(Quadrature, Quad8AndQuad9AreFpg9CornersMidEdgesCentre) {
  const double a = std::sqrt(3.0 / 5), c = 25.0 / 81, e = 40.0 / 81, m = 64.0 / 81;
  const std::vector<Row> fpg9{{-a, -a, c}, {a, -a, c}, {a, a, c}, {-a, a, c}, {0, -a, e},
                              {a, 0, e},   {0, a, e},  {-a, 0, e}, {0, 0, m}};
  for (CellType t : {CellType::QUAD8, CellType::QUAD9})
    for (bool axis : {false, true}) {
      const auto& r = fullSurfaceRule(t, axis);
      expectTable(r, fpg9, "QUAD8/9 FPG9");
      EXPECT_EQ(exactDegree(r, false), 5);
      EXPECT_EQ(r.degree, 5);
    }
}

TEST(Quadrature, EdgeRulesAreFpg2AndFpg3) {
  const double a = 1 / std::sqrt(3.0);
  const auto& s2 = fullEdgeRule(CellType::SEG2);
  ASSERT_EQ(s2.size(), 2);
  EXPECT_NEAR(s2.points[0](0), a, 1e-15);
  EXPECT_NEAR(s2.points[1](0), -a, 1e-15);
  EXPECT_NEAR(s2.weights[0], 1.0, 1e-15);
  EXPECT_NEAR(s2.weights[1], 1.0, 1e-15);
  EXPECT_EQ(exactDegree(s2), 3);
  const double b = std::sqrt(3.0 / 5);
  const double x[3] = {-b, 0, b}, w[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  const auto& s3 = fullEdgeRule(CellType::SEG3);
  ASSERT_EQ(s3.size(), 3);
  for (int q = 0; q < 3; ++q) {
    EXPECT_NEAR(s3.points[q](0), x[q], 1e-15) << q;
    EXPECT_NEAR(s3.weights[q], w[q], 1e-15) << q;
  }
  EXPECT_EQ(exactDegree(s3), 5);
  EXPECT_EQ(s3.degree, 5);
}
