// Lagrange shape functions on code_aster's reference cells, values and
// derivatives with respect to the reference coordinates.
//   SEG2, SEG3 on [-1,1]: nodes -1, +1 (then 0 for SEG3).
//   TRIA3, TRIA6 on (0,0),(1,0),(0,1); TRIA6 mids of edges 1-2, 2-3, 3-1.
//   QUAD4, QUAD8, QUAD9 on [-1,1]^2: corners counterclockwise from (-1,-1),
//   mids of edges 1-2, 2-3, 3-4, 4-1, then the centre (QUAD9).
// Header-only and allocation-free: these run inside element loops.
#pragma once
#include <Eigen/Core>

#include "fem/cell_type.hpp"

namespace aster::fem {

template <int Dim, int Nodes>
struct CellBase {
  static constexpr int dim = Dim;
  static constexpr int nodes = Nodes;
  using Point = Eigen::Matrix<double, Dim, 1>;
  using Values = Eigen::Matrix<double, Nodes, 1>;
  using Gradients = Eigen::Matrix<double, Nodes, Dim>;  // row a: dN_a/dxi_j
  using Nodes_ = Eigen::Matrix<double, Nodes, Dim>;
};

template <CellType T>
struct Cell;

// ---------------------------------------------------------------- segments
template <>
struct Cell<CellType::SEG2> : CellBase<1, 2> {
  static constexpr CellType type = CellType::SEG2;
  static constexpr int degree = 1;  // polynomial degree of the map
  static Values values(const Point& p) {
    const double s = p(0);
    return Values(0.5 * (1 - s), 0.5 * (1 + s));
  }
  static Gradients gradients(const Point&) { return Gradients(-0.5, 0.5); }
  static Values secondDerivatives(const Point&) { return Values::Zero(); }
  static Nodes_ referenceNodes() { return Nodes_(-1.0, 1.0); }
};

template <>
struct Cell<CellType::SEG3> : CellBase<1, 3> {
  static constexpr CellType type = CellType::SEG3;
  static constexpr int degree = 2;
  static Values values(const Point& p) {
    const double s = p(0);
    return Values(0.5 * s * (s - 1), 0.5 * s * (s + 1), 1 - s * s);
  }
  static Gradients gradients(const Point& p) {
    const double s = p(0);
    return Gradients(s - 0.5, s + 0.5, -2 * s);
  }
  // d2N/dxi2, constant: what curvature terms of contact need.
  static Values secondDerivatives(const Point&) { return Values(1.0, 1.0, -2.0); }
  static Nodes_ referenceNodes() { return Nodes_(-1.0, 1.0, 0.0); }
};

// --------------------------------------------------------------- triangles
template <>
struct Cell<CellType::TRIA3> : CellBase<2, 3> {
  static constexpr CellType type = CellType::TRIA3;
  static constexpr int degree = 1;
  static Values values(const Point& p) { return Values(1 - p(0) - p(1), p(0), p(1)); }
  static Gradients gradients(const Point&) {
    Gradients g;
    g << -1, -1, 1, 0, 0, 1;
    return g;
  }
  static Nodes_ referenceNodes() {
    Nodes_ x;
    x << 0, 0, 1, 0, 0, 1;
    return x;
  }
};

template <>
struct Cell<CellType::TRIA6> : CellBase<2, 6> {
  static constexpr CellType type = CellType::TRIA6;
  static constexpr int degree = 2;
  static Values values(const Point& p) {
    const double l1 = 1 - p(0) - p(1), l2 = p(0), l3 = p(1);
    Values v;
    v << l1 * (2 * l1 - 1), l2 * (2 * l2 - 1), l3 * (2 * l3 - 1), 4 * l1 * l2, 4 * l2 * l3, 4 * l3 * l1;
    return v;
  }
  static Gradients gradients(const Point& p) {
    // Barycentric l1 = 1-x-y, l2 = x, l3 = y; dl1 = (-1,-1), dl2 = (1,0), dl3 = (0,1).
    const double l1 = 1 - p(0) - p(1), l2 = p(0), l3 = p(1);
    const double a = 4 * l1 - 1;
    Gradients g;
    g << -a, -a,                       //
        4 * l2 - 1, 0,                 //
        0, 4 * l3 - 1,                 //
        4 * (l1 - l2), -4 * l2,        //
        4 * l3, 4 * l2,                //
        -4 * l3, 4 * (l1 - l3);
    return g;
  }
  static Nodes_ referenceNodes() {
    Nodes_ x;
    x << 0, 0, 1, 0, 0, 1, 0.5, 0, 0.5, 0.5, 0, 0.5;
    return x;
  }
};

// ------------------------------------------------------------- quadrangles
namespace detail {
// Corner signs of the reference square, counterclockwise from (-1,-1).
inline constexpr double kQuadXi[4] = {-1, 1, 1, -1};
inline constexpr double kQuadEta[4] = {-1, -1, 1, 1};
// 1D quadratic Lagrange basis on nodes -1, 0, 1 (index 0, 1, 2), with derivative.
inline double lag2(int i, double s) { return i == 0 ? 0.5 * s * (s - 1) : (i == 1 ? 1 - s * s : 0.5 * s * (s + 1)); }
inline double lag2d(int i, double s) { return i == 0 ? s - 0.5 : (i == 1 ? -2 * s : s + 0.5); }
}  // namespace detail

template <>
struct Cell<CellType::QUAD4> : CellBase<2, 4> {
  static constexpr CellType type = CellType::QUAD4;
  static constexpr int degree = 1;
  static Values values(const Point& p) {
    Values v;
    for (int a = 0; a < 4; ++a) v(a) = 0.25 * (1 + detail::kQuadXi[a] * p(0)) * (1 + detail::kQuadEta[a] * p(1));
    return v;
  }
  static Gradients gradients(const Point& p) {
    Gradients g;
    for (int a = 0; a < 4; ++a) {
      const double xa = detail::kQuadXi[a], ya = detail::kQuadEta[a];
      g(a, 0) = 0.25 * xa * (1 + ya * p(1));
      g(a, 1) = 0.25 * ya * (1 + xa * p(0));
    }
    return g;
  }
  static Nodes_ referenceNodes() {
    Nodes_ x;
    x << -1, -1, 1, -1, 1, 1, -1, 1;
    return x;
  }
};

template <>
struct Cell<CellType::QUAD8> : CellBase<2, 8> {
  static constexpr CellType type = CellType::QUAD8;
  static constexpr int degree = 2;
  static Values values(const Point& p) {
    const double x = p(0), y = p(1);
    Values v;
    for (int a = 0; a < 4; ++a) {
      const double s = detail::kQuadXi[a] * x, t = detail::kQuadEta[a] * y;
      v(a) = 0.25 * (1 + s) * (1 + t) * (s + t - 1);
    }
    v(4) = 0.5 * (1 - x * x) * (1 - y);
    v(5) = 0.5 * (1 + x) * (1 - y * y);
    v(6) = 0.5 * (1 - x * x) * (1 + y);
    v(7) = 0.5 * (1 - x) * (1 - y * y);
    return v;
  }
  static Gradients gradients(const Point& p) {
    const double x = p(0), y = p(1);
    Gradients g;
    for (int a = 0; a < 4; ++a) {
      const double xa = detail::kQuadXi[a], ya = detail::kQuadEta[a];
      const double s = xa * x, t = ya * y;
      g(a, 0) = 0.25 * xa * (1 + t) * (2 * s + t);
      g(a, 1) = 0.25 * ya * (1 + s) * (s + 2 * t);
    }
    g(4, 0) = -x * (1 - y);       g(4, 1) = -0.5 * (1 - x * x);
    g(5, 0) = 0.5 * (1 - y * y);  g(5, 1) = -y * (1 + x);
    g(6, 0) = -x * (1 + y);       g(6, 1) = 0.5 * (1 - x * x);
    g(7, 0) = -0.5 * (1 - y * y); g(7, 1) = -y * (1 - x);
    return g;
  }
  static Nodes_ referenceNodes() {
    Nodes_ x;
    x << -1, -1, 1, -1, 1, 1, -1, 1, 0, -1, 1, 0, 0, 1, -1, 0;
    return x;
  }
};

template <>
struct Cell<CellType::QUAD9> : CellBase<2, 9> {
  static constexpr CellType type = CellType::QUAD9;
  static constexpr int degree = 2;
  // Index (0,1,2 for -1,0,1) of each node along xi and eta.
  static constexpr int kI[9] = {0, 2, 2, 0, 1, 2, 1, 0, 1};
  static constexpr int kJ[9] = {0, 0, 2, 2, 0, 1, 2, 1, 1};
  static Values values(const Point& p) {
    Values v;
    for (int a = 0; a < 9; ++a) v(a) = detail::lag2(kI[a], p(0)) * detail::lag2(kJ[a], p(1));
    return v;
  }
  static Gradients gradients(const Point& p) {
    Gradients g;
    for (int a = 0; a < 9; ++a) {
      g(a, 0) = detail::lag2d(kI[a], p(0)) * detail::lag2(kJ[a], p(1));
      g(a, 1) = detail::lag2(kI[a], p(0)) * detail::lag2d(kJ[a], p(1));
    }
    return g;
  }
  static Nodes_ referenceNodes() {
    Nodes_ x;
    x << -1, -1, 1, -1, 1, 1, -1, 1, 0, -1, 1, 0, 0, 1, -1, 0, 0, 0;
    return x;
  }
};

}  // namespace aster::fem
