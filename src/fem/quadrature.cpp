#include "fem/quadrature.hpp"

#include <array>
#include <cmath>
#include <initializer_list>
#include <string>

#include "core/error.hpp"

namespace aster::fem {
namespace {

// Nodes are the roots of the Legendre polynomial P_n, found by Newton from the
// classical cosine guess; weights 2 / ((1 - x^2) P_n'(x)^2).
QuadratureRule<1> buildGaussLegendre(int n) {
  QuadratureRule<1> r;
  r.degree = 2 * n - 1;
  r.points.resize(n);
  r.weights.resize(n);
  const double pi = std::acos(-1.0);
  for (int i = 0; i < n; ++i) {
    double x = -std::cos(pi * (i + 0.75) / (n + 0.5));
    double dp = 1;
    for (int iter = 0; iter < 100; ++iter) {
      double p0 = 1, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      const double pn = n == 0 ? 1 : p1, pm = n == 1 ? 1 : p0;
      dp = n * (x * pn - pm) / (x * x - 1);
      const double dx = pn / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    // One more evaluation of the derivative at the converged root.
    double p0 = 1, p1 = x;
    for (int k = 2; k <= n; ++k) {
      const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
      p0 = p1;
      p1 = p2;
    }
    dp = n * (x * p1 - (n == 1 ? 1 : p0)) / (x * x - 1);
    r.points[i](0) = x;
    r.weights[i] = 2 / ((1 - x * x) * dp * dp);
  }
  return r;
}

QuadratureRule<2> buildQuadrangle(int n) {
  const QuadratureRule<1>& g = gaussLegendre(n);
  QuadratureRule<2> r;
  r.degree = g.degree;  // per direction; total degree 2n-1 is exact too
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      r.points.emplace_back(g.points[i](0), g.points[j](0));
      r.weights.push_back(g.weights[i] * g.weights[j]);
    }
  return r;
}

// Helpers adding symmetric orbits in barycentric coordinates (l1, l2, l3),
// with weights normalised to the triangle of area 1/2.
void addCentroid(QuadratureRule<2>& r, double w) {
  r.points.emplace_back(1.0 / 3, 1.0 / 3);
  r.weights.push_back(0.5 * w);
}
// Orbit of (a, b, b): 3 points.
void addOrbit3(QuadratureRule<2>& r, double a, double b, double w) {
  const double l[3][3] = {{a, b, b}, {b, a, b}, {b, b, a}};
  for (auto& p : l) {
    r.points.emplace_back(p[1], p[2]);
    r.weights.push_back(0.5 * w);
  }
}
// Orbit of (a, b, c) all different: 6 points.
void addOrbit6(QuadratureRule<2>& r, double a, double b, double c, double w) {
  const double l[6][3] = {{a, b, c}, {a, c, b}, {b, a, c}, {b, c, a}, {c, a, b}, {c, b, a}};
  for (auto& p : l) {
    r.points.emplace_back(p[1], p[2]);
    r.weights.push_back(0.5 * w);
  }
}

QuadratureRule<2> buildTriangle(int degree) {
  QuadratureRule<2> r;
  switch (degree) {
    case 1:
      addCentroid(r, 1.0);
      r.degree = 1;
      break;
    case 2:
      addOrbit3(r, 2.0 / 3, 1.0 / 6, 1.0 / 3);
      r.degree = 2;
      break;
    case 3:
    case 4:  // Dunavant (1985), degree 4, 6 points.
      addOrbit3(r, 0.108103018168070, 0.445948490915965, 0.223381589678011);
      addOrbit3(r, 0.816847572980459, 0.091576213509771, 0.109951743655322);
      r.degree = 4;
      break;
    case 5: {  // Radon's 7-point rule, closed form.
      const double s = std::sqrt(15.0);
      addCentroid(r, 9.0 / 40);
      addOrbit3(r, (9 + 2 * s) / 21, (6 - s) / 21, (155 - s) / 1200);
      addOrbit3(r, (9 - 2 * s) / 21, (6 + s) / 21, (155 + s) / 1200);
      r.degree = 5;
      break;
    }
    case 6:  // Dunavant (1985), degree 6, 12 points.
      addOrbit3(r, 0.501426509658179, 0.249286745170910, 0.116786275726379);
      addOrbit3(r, 0.873821971016996, 0.063089014491502, 0.050844906370207);
      addOrbit6(r, 0.053145049844817, 0.310352451033784, 0.636502499121399, 0.082851075618374);
      r.degree = 6;
      break;
    default:
      throw Error("triangle quadrature: degree " + std::to_string(degree) + " not available (1.." +
                  std::to_string(kMaxTriangleDegree) + ")");
  }
  return r;
}

}  // namespace

const QuadratureRule<1>& gaussLegendre(int points) {
  static const auto rules = [] {
    std::array<QuadratureRule<1>, kMaxGaussPoints + 1> a;
    for (int n = 1; n <= kMaxGaussPoints; ++n) a[n] = buildGaussLegendre(n);
    return a;
  }();
  if (points < 1 || points > kMaxGaussPoints)
    throw Error("Gauss-Legendre rule: " + std::to_string(points) + " points requested, 1.." +
                std::to_string(kMaxGaussPoints) + " available");
  return rules[points];
}

const QuadratureRule<2>& gaussQuadrangle(int n) {
  static const auto rules = [] {
    std::array<QuadratureRule<2>, kMaxGaussPoints + 1> a;
    for (int k = 1; k <= kMaxGaussPoints; ++k) a[k] = buildQuadrangle(k);
    return a;
  }();
  if (n < 1 || n > kMaxGaussPoints)
    throw Error("quadrangle Gauss rule: " + std::to_string(n) + " points per direction requested, 1.." +
                std::to_string(kMaxGaussPoints) + " available");
  return rules[n];
}

const QuadratureRule<2>& gaussTriangle(int degree) {
  static const auto rules = [] {
    std::array<QuadratureRule<2>, kMaxTriangleDegree + 1> a;
    for (int d = 1; d <= kMaxTriangleDegree; ++d) a[d] = buildTriangle(d);
    return a;
  }();
  if (degree < 1 || degree > kMaxTriangleDegree) buildTriangle(degree);  // throws with the message
  return rules[degree];
}

const QuadratureRule<1>& edgeRule(int degree) {
  return gaussLegendre(degree <= 1 ? 1 : (degree + 2) / 2);
}

const QuadratureRule<2>& surfaceRule(CellType t, int degree) {
  switch (t) {
    case CellType::TRIA3:
    case CellType::TRIA6:
      return gaussTriangle(degree < 1 ? 1 : degree);
    case CellType::QUAD4:
    case CellType::QUAD8:
    case CellType::QUAD9:
      return gaussQuadrangle(degree <= 1 ? 1 : (degree + 2) / 2);
    default:
      throw Error(std::string("surface quadrature requested for the edge cell ") + cellName(t));
  }
}

namespace {

// code_aster's families (elraga), with its coordinates, weights and point order.
QuadratureRule<2> asterRule(std::initializer_list<std::array<double, 3>> xyw, int degree) {
  QuadratureRule<2> r;
  for (const auto& p : xyw) {
    r.points.emplace_back(p[0], p[1]);
    r.weights.push_back(p[2]);
  }
  r.degree = degree;
  return r;
}

// TRIA FPG1: the centroid.
const QuadratureRule<2>& triangleFpg1() {
  static const auto r = asterRule({{1.0 / 3, 1.0 / 3, 0.5}}, 1);
  return r;
}
// TRIA FPG3: three interior points, each at 1/6 from two sides.
const QuadratureRule<2>& triangleFpg3() {
  static const auto r = asterRule({{1.0 / 6, 1.0 / 6, 1.0 / 6}, {2.0 / 3, 1.0 / 6, 1.0 / 6}, {1.0 / 6, 2.0 / 3, 1.0 / 6}}, 2);
  return r;
}
// TRIA FPG6: Dunavant's degree-4 rule, the orbit near the vertices first.
const QuadratureRule<2>& triangleFpg6() {
  static const auto r = [] {
    const double a = 0.445948490915965, b = 0.091576213509771;
    const double wa = 0.111690794839005, wb = 0.054975871827661;
    return asterRule({{b, b, wb}, {1 - 2 * b, b, wb}, {b, 1 - 2 * b, wb},
                      {a, 1 - 2 * a, wa}, {a, a, wa}, {1 - 2 * a, a, wa}},
                     4);
  }();
  return r;
}
// QUAD FPG4: 2x2 Gauss points counterclockwise from (-,-).
const QuadratureRule<2>& quadrangleFpg4() {
  static const auto r = [] {
    const double a = 1 / std::sqrt(3.0);
    return asterRule({{-a, -a, 1.0}, {a, -a, 1.0}, {a, a, 1.0}, {-a, a, 1.0}}, 3);
  }();
  return r;
}
// QUAD FPG9: 3x3 Gauss points, the corners counterclockwise from (-,-), then the
// mid-edges counterclockwise from the edge y = -a, then the centre.
const QuadratureRule<2>& quadrangleFpg9() {
  static const auto r = [] {
    const double a = std::sqrt(0.6), wc = 25.0 / 81, we = 40.0 / 81, wm = 64.0 / 81;
    return asterRule({{-a, -a, wc}, {a, -a, wc}, {a, a, wc}, {-a, a, wc},
                      {0, -a, we}, {a, 0, we}, {0, a, we}, {-a, 0, we}, {0, 0, wm}},
                     5);
  }();
  return r;
}

QuadratureRule<1> asterEdgeRule(std::initializer_list<std::array<double, 2>> xw, int degree) {
  QuadratureRule<1> r;
  for (const auto& p : xw) {
    r.points.emplace_back(p[0]);
    r.weights.push_back(p[1]);
  }
  r.degree = degree;
  return r;
}

}  // namespace

const QuadratureRule<2>& fullSurfaceRule(CellType t, bool axisymmetric) {
  switch (t) {
    case CellType::TRIA3: return triangleFpg1();
    case CellType::TRIA6: return axisymmetric ? triangleFpg6() : triangleFpg3();
    case CellType::QUAD4: return quadrangleFpg4();
    case CellType::QUAD8:
    case CellType::QUAD9: return quadrangleFpg9();
    default: break;
  }
  throw Error(std::string("surface quadrature requested for the edge cell ") + cellName(t));
}

const QuadratureRule<1>& fullEdgeRule(CellType t) {
  // SEG2 FPG2: +a first; SEG3 FPG3: -a, 0, +a.
  static const auto seg2 = [] {
    const double a = 1 / std::sqrt(3.0);
    return asterEdgeRule({{a, 1.0}, {-a, 1.0}}, 3);
  }();
  static const auto seg3 = [] {
    const double a = std::sqrt(0.6);
    return asterEdgeRule({{-a, 5.0 / 9}, {0.0, 8.0 / 9}, {a, 5.0 / 9}}, 5);
  }();
  switch (t) {
    case CellType::SEG2: return seg2;
    case CellType::SEG3: return seg3;
    default: break;
  }
  throw Error(std::string("edge quadrature requested for the surface cell ") + cellName(t));
}

}  // namespace aster::fem
