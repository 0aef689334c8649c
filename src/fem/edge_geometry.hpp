// Geometry of an edge cell (SEG2, SEG3) lying in the XY plane, at one reference
// point xi in [-1,1]: what boundary loads and contact need.
// Normal convention: walking the edge from node 1 to node 2, n = (dy, -dx)/|.|,
// i.e. the outward normal of a boundary walked counterclockwise.
#pragma once
#include <cmath>
#include <string>

#include <Eigen/Core>

#include "core/error.hpp"
#include "fem/shape_functions.hpp"

namespace aster::fem {

template <CellType T>
using EdgeCoords = Eigen::Matrix<double, Cell<T>::nodes, 2>;

struct EdgeFrame {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();    // x(xi)
  Eigen::Vector2d dx = Eigen::Vector2d::Zero();       // dx/dxi (unnormalised tangent)
  Eigen::Vector2d d2x = Eigen::Vector2d::Zero();      // d2x/dxi2 (zero for SEG2)
  double jacobian = 0;      // |dx/dxi|: ds = jacobian * dxi
  Eigen::Vector2d tangent = Eigen::Vector2d::Zero();  // dx/dxi / |dx/dxi|
  Eigen::Vector2d normal = Eigen::Vector2d::Zero();   // (t_y, -t_x)
  double curvature = 0;     // signed: (x' ^ x'') / |x'|^3, > 0 when the edge turns left
  Eigen::Vector2d dNormal = Eigen::Vector2d::Zero();  // dn/dxi = curvature * jacobian * tangent
  Eigen::Vector2d dTangent = Eigen::Vector2d::Zero(); // dt/dxi = -curvature * jacobian * normal
};

template <CellType T>
EdgeFrame edgeFrame(const EdgeCoords<T>& X, double xi) {
  using C = Cell<T>;
  static_assert(C::dim == 1, "edgeFrame() is for edge cells");
  const typename C::Point p(xi);
  EdgeFrame f;
  f.point = X.transpose() * C::values(p);
  f.dx = X.transpose() * C::gradients(p);
  f.d2x = X.transpose() * C::secondDerivatives(p);
  f.jacobian = f.dx.norm();
  if (!(f.jacobian > 0))
    throw Error(std::string("degenerate ") + cellName(T) + " edge: zero length element at xi = " + std::to_string(xi));
  f.tangent = f.dx / f.jacobian;
  f.normal = Eigen::Vector2d(f.tangent(1), -f.tangent(0));
  f.curvature = (f.dx(0) * f.d2x(1) - f.dx(1) * f.d2x(0)) / (f.jacobian * f.jacobian * f.jacobian);
  f.dNormal = f.curvature * f.jacobian * f.tangent;
  f.dTangent = -f.curvature * f.jacobian * f.normal;
  return f;
}

}  // namespace aster::fem
