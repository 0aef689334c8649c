// The isoparametric map of a surface cell in the XY plane: x(xi) = sum_a N_a(xi) X_a.
// Node coordinates are given as a (nodes x 2) matrix, one row per node, in the
// cell's node order.
#pragma once
#include <cmath>
#include <string>

#include <Eigen/Core>
#include <Eigen/LU>

#include "core/error.hpp"
#include "fem/shape_functions.hpp"

namespace aster::fem {

template <CellType T>
using NodeCoords = Eigen::Matrix<double, Cell<T>::nodes, 2>;

// Jacobian J_ij = dx_i/dxi_j at one point, its determinant and inverse.
struct Jacobian2 {
  Eigen::Matrix2d J;
  Eigen::Matrix2d inverse;
  double det = 0;
};

template <CellType T>
inline Eigen::Vector2d mapPoint(const NodeCoords<T>& X, const typename Cell<T>::Values& N) {
  return X.transpose() * N;
}

template <CellType T>
inline Eigen::Vector2d mapPoint(const NodeCoords<T>& X, const typename Cell<T>::Point& xi) {
  return X.transpose() * Cell<T>::values(xi);
}

// Throws aster::Error for a singular map; out of line so that element code
// compiled for another instruction set holds no copy of the exception's code.
[[noreturn]] void throwSingularMap(const char* cell, double det);

// Throws when the map is singular or folds (detJ <= 0): a degenerate cell or one
// whose nodes are numbered clockwise.
template <CellType T>
inline Jacobian2 jacobian(const NodeCoords<T>& X, const typename Cell<T>::Gradients& dN) {
  static_assert(Cell<T>::dim == 2, "jacobian() is for surface cells");
  Jacobian2 j;
  j.J = X.transpose() * dN;
  j.det = j.J.determinant();
  if (!(j.det > 0)) throwSingularMap(cellName(T), j.det);
  j.inverse << j.J(1, 1), -j.J(0, 1), -j.J(1, 0), j.J(0, 0);
  j.inverse /= j.det;
  return j;
}

// Gradients of the shape functions with respect to x: row a is grad_x N_a.
template <CellType T>
inline typename Cell<T>::Gradients physicalGradients(const typename Cell<T>::Gradients& dN, const Jacobian2& j) {
  return dN * j.inverse;
}

// Reference coordinates of the physical point x (Newton on the map). Throws when
// Newton does not converge; the result may lie outside the reference cell when x
// is outside the cell, which callers can test.
template <CellType T>
typename Cell<T>::Point inverseMap(const NodeCoords<T>& X, const Eigen::Vector2d& x, double tolerance = 1e-13,
                                   int maxIterations = 50) {
  using C = Cell<T>;
  typename C::Point xi = C::referenceNodes().colwise().mean().transpose();
  const double scale = (X.colwise().maxCoeff() - X.colwise().minCoeff()).norm();
  for (int it = 0; it < maxIterations; ++it) {
    const Eigen::Vector2d r = x - X.transpose() * C::values(xi);
    if (r.norm() <= tolerance * scale) return xi;
    const Eigen::Matrix2d J = X.transpose() * C::gradients(xi);
    xi += J.partialPivLu().solve(r);
  }
  throw Error(std::string("inverse isoparametric map of a ") + cellName(T) + " did not converge for point (" +
              std::to_string(x(0)) + ", " + std::to_string(x(1)) + ")");
}

}  // namespace aster::fem
