// External load kernels, per unit thickness, local DOF order node-major
// (fx_1, fy_1, fx_2, ...). Data are callables of the reference point X
// (Eigen::Vector2d), so formulas of (X, Y) plug in directly.
//   FORCE_CONTOUR: dead traction t(X) per unit reference length on an edge;
//   FORCE_INTERNE: body force b(X) per unit reference area on a surface cell;
//   PRES_REP: follower pressure p(X) on the deformed edge, f = -int p n ds
//     (current configuration; n = (dy, -dx)/|.| walking node 1 -> node 2, so a
//     positive p pushes against the outward normal of a counterclockwise boundary).
// AXIS (axisymmetric = true; r = X, the axis along Y): per radian, each integral
// weighted by the radius: the reference X for dead loads, the current x = X + u_x
// for follower pressures (whose tangent then has the term of dr/du).
#pragma once
#include <type_traits>
#include <Eigen/Core>

#include "fem/edge_geometry.hpp"
#include "fem/isoparametric.hpp"
#include "fem/quadrature.hpp"

namespace aster::mechanics {

using fem::CellType;

template <CellType T>
using EdgeVector = Eigen::Matrix<double, 2 * fem::Cell<T>::nodes, 1>;
template <CellType T>
using EdgeMatrix = Eigen::Matrix<double, 2 * fem::Cell<T>::nodes, 2 * fem::Cell<T>::nodes>;

// Default load quadrature: element degree + data degree, with data taken as
// smooth: 3 points on SEG2, 4 on SEG3; 3x3 on QUAD4, 4x4 on QUAD8/9, degree 4
// on TRIA3, degree 6 on TRIA6.
constexpr int defaultEdgeLoadPoints(CellType t) { return t == CellType::SEG2 ? 3 : 4; }
inline const fem::QuadratureRule<2>& defaultSurfaceLoadRule(CellType t) {
  switch (t) {
    case CellType::TRIA3: return fem::gaussTriangle(4);
    case CellType::TRIA6: return fem::gaussTriangle(6);
    case CellType::QUAD4: return fem::gaussQuadrangle(3);
    default: return fem::gaussQuadrangle(4);
  }
}

// Dead edge traction: f_a = int N_a t(X) |dX/dxi| (r) dxi.
template <CellType T, class Traction>
EdgeVector<T> deadEdgeTraction(const fem::EdgeCoords<T>& X, const Traction& traction, bool axisymmetric = false,
                               int points = defaultEdgeLoadPoints(T)) {
  using C = fem::Cell<T>;
  const auto& rule = fem::gaussLegendre(points);
  EdgeVector<T> f = EdgeVector<T>::Zero();
  for (int q = 0; q < rule.size(); ++q) {
    const auto N = C::values(rule.points[q]);
    const Eigen::Vector2d dX = X.transpose() * C::gradients(rule.points[q]);
    const Eigen::Vector2d x = X.transpose() * N;
    const Eigen::Vector2d t = traction(x);
    const double w = rule.weights[q] * dX.norm() * (axisymmetric ? x(0) : 1.0);
    for (int a = 0; a < C::nodes; ++a) f.template segment<2>(2 * a) += (w * N(a)) * t;
  }
  return f;
}

// Body force on a surface cell: f_a = int N_a b(X) detJ (r).
template <CellType T, class Force>
Eigen::Matrix<double, 2 * fem::Cell<T>::nodes, 1> bodyForce(const fem::NodeCoords<T>& X, const Force& force,
                                                           bool axisymmetric = false,
                                                           const fem::QuadratureRule<2>& rule =
                                                               defaultSurfaceLoadRule(T)) {
  using C = fem::Cell<T>;
  Eigen::Matrix<double, 2 * C::nodes, 1> f = Eigen::Matrix<double, 2 * C::nodes, 1>::Zero();
  for (int q = 0; q < rule.size(); ++q) {
    const auto N = C::values(rule.points[q]);
    const Eigen::Vector2d x = X.transpose() * N;
    const double w = rule.weights[q] * fem::jacobian<T>(X, C::gradients(rule.points[q])).det *
                     (axisymmetric ? x(0) : 1.0);
    const Eigen::Vector2d b = force(x);
    for (int a = 0; a < C::nodes; ++a) f.template segment<2>(2 * a) += (w * N(a)) * b;
  }
  return f;
}

// Follower pressure on the deformed edge x = X + u:
//   f_a = -int p N_a (dy/dxi, -dx/dxi) (r) dxi   (the external force; AXIS: r = X + u_x),
//   dfdu = df/du (not symmetric in general). In a Newton tangent for the
//   residual f_int - f_ext this enters as K_int - dfdu. Either output may be null.
// The pressure is pressure(X) at the reference point X, or, when it takes
// (X, x, dpdx), a function of the current point x too that writes its gradient
// dp/dx in dpdx (code_aster's XF, YF): dfdu then has the term of dp/du.
template <CellType T, class Pressure>
void followerPressure(const fem::EdgeCoords<T>& X, const EdgeVector<T>& u, const Pressure& pressure,
                      EdgeVector<T>* f, EdgeMatrix<T>* dfdu, bool axisymmetric = false,
                      int points = defaultEdgeLoadPoints(T)) {
  using C = fem::Cell<T>;
  constexpr bool ofCurrentPoint =
      std::is_invocable_r_v<double, const Pressure&, const Eigen::Vector2d&, const Eigen::Vector2d&,
                            Eigen::Vector2d*>;
  const auto& rule = fem::gaussLegendre(points);
  const Eigen::Map<const Eigen::Matrix<double, 2, C::nodes>> U(u.data());
  if (f) f->setZero();
  if (dfdu) dfdu->setZero();
  for (int q = 0; q < rule.size(); ++q) {
    const auto N = C::values(rule.points[q]);
    const auto dN = C::gradients(rule.points[q]);
    const Eigen::Vector2d dx = X.transpose() * dN + U * dN;
    const Eigen::Vector2d Xq = X.transpose() * N;
    Eigen::Vector2d dpdx = Eigen::Vector2d::Zero();
    double pq;
    if constexpr (ofCurrentPoint) {
      pq = pressure(Xq, Eigen::Vector2d(Xq + U * N), &dpdx);
    } else {
      pq = pressure(Xq);
    }
    const double p = rule.weights[q] * pq;
    const double r = axisymmetric ? Xq(0) + (U * N)(0) : 1.0;
    const double wp = p * r;
    for (int a = 0; a < C::nodes; ++a) {
      if (f) {
        (*f)(2 * a) -= wp * N(a) * dx(1);
        (*f)(2 * a + 1) += wp * N(a) * dx(0);
      }
      if (dfdu)
        for (int b = 0; b < C::nodes; ++b) {
          (*dfdu)(2 * a, 2 * b + 1) -= wp * N(a) * dN(b);
          (*dfdu)(2 * a + 1, 2 * b) += wp * N(a) * dN(b);
          if (axisymmetric) {  // dr/du_bx = N_b
            (*dfdu)(2 * a, 2 * b) -= p * N(a) * dx(1) * N(b);
            (*dfdu)(2 * a + 1, 2 * b) += p * N(a) * dx(0) * N(b);
          }
          if (ofCurrentPoint)  // dp/du_bk = dp/dx_k N_b
            for (int k = 0; k < 2; ++k) {
              const double dwp = rule.weights[q] * r * dpdx(k) * N(b);
              (*dfdu)(2 * a, 2 * b + k) -= dwp * N(a) * dx(1);
              (*dfdu)(2 * a + 1, 2 * b + k) += dwp * N(a) * dx(0);
            }
        }
    }
  }
}

}  // namespace aster::mechanics
