// Shape function values and reference gradients tabulated at the points of a
// quadrature rule, computed once per (cell type, rule) and reused by every
// element: the element loop only multiplies fixed-size matrices.
#pragma once
#include <vector>

#include "fem/quadrature.hpp"
#include "fem/shape_functions.hpp"

namespace aster::fem {

template <CellType T>
class ShapeTable {
 public:
  using C = Cell<T>;
  using Point = typename C::Point;
  using Values = typename C::Values;
  using Gradients = typename C::Gradients;

  explicit ShapeTable(const QuadratureRule<C::dim>& rule) {
    const int n = rule.size();
    points_ = rule.points;
    weights_ = rule.weights;
    values_.resize(n);
    gradients_.resize(n);
    for (int q = 0; q < n; ++q) {
      values_[q] = C::values(rule.points[q]);
      gradients_[q] = C::gradients(rule.points[q]);
    }
  }

  int size() const { return static_cast<int>(weights_.size()); }
  const Point& point(int q) const { return points_[q]; }
  double weight(int q) const { return weights_[q]; }
  const Values& values(int q) const { return values_[q]; }
  const Gradients& gradients(int q) const { return gradients_[q]; }

 private:
  std::vector<Point> points_;
  std::vector<double> weights_;
  std::vector<Values> values_;
  std::vector<Gradients> gradients_;
};

}  // namespace aster::fem
