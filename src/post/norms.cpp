#include "post/norms.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "fem/mesh_cell_type.hpp"
#include "fem/cell_type.hpp"
#include "fem/isoparametric.hpp"
#include "fem/quadrature.hpp"
#include "fem/shape_functions.hpp"

namespace aster::post {
namespace {

// The cell's node coordinates (x, y), a row per node.
template <fem::CellType T>
fem::NodeCoords<T> coordinatesOf(const mesh::Mesh& mesh, int cell) {
  const auto nodes = mesh.cellNodes(cell);
  fem::NodeCoords<T> X;
  for (int a = 0; a < fem::Cell<T>::nodes; ++a) {
    const auto p = mesh.node(nodes[a]);
    X(a, 0) = p(0);
    X(a, 1) = p(1);
  }
  return X;
}

struct Accumulator {
  const NodalValues& field;
  const std::vector<ExactFunction>& exact;
  double err2 = 0, exact2 = 0, comp2 = 0, measure = 0;

  // One quadrature point: weight w (|J| included), position (x, y), field values
  // interpolated as sum_a N[a] * values[nodes[a]].
  template <class Shape>
  void add(double w, double x, double y, const Shape& N, const int* nodes, int count) {
    measure += w;
    const auto& v = *field.values;
    for (std::size_t k = 0; k < field.components.size(); ++k) {
      const int c = field.components[k];
      double uh = 0;
      for (int a = 0; a < count; ++a) uh += N[a] * v[static_cast<std::size_t>(nodes[a]) * field.componentCount + c];
      const double u = exact.empty() ? 0.0 : exact[k](x, y);
      const double wc = field.weights.empty() ? 1.0 : field.weights[k];
      err2 += w * wc * (uh - u) * (uh - u);
      exact2 += w * wc * u * u;
      comp2 += w * wc * uh * uh;
    }
  }
};

template <fem::CellType T>
void surfaceCell(const mesh::Mesh& mesh, int cell, Accumulator& acc) {
  using C = fem::Cell<T>;
  const auto nodes = mesh.cellNodes(cell);
  const fem::NodeCoords<T> X = coordinatesOf<T>(mesh, cell);
  // Field of degree p, exact solutions smooth: a rule exact to 2p+2 at least
  // (2p+4 on quadrangles, whose map adds degree; the triangle rules stop at 6).
  const bool triangle = T == fem::CellType::TRIA3 || T == fem::CellType::TRIA6;
  const int degree = triangle ? std::min(2 * C::degree + 2, fem::kMaxTriangleDegree) : 2 * C::degree + 4;
  const auto& rule = fem::surfaceRule(T, degree);
  for (int q = 0; q < rule.size(); ++q) {
    const auto N = C::values(rule.points[q]);
    const auto J = fem::jacobian<T>(X, C::gradients(rule.points[q]));
    const Eigen::Vector2d x = fem::mapPoint<T>(X, N);
    double Na[C::nodes];
    for (int a = 0; a < C::nodes; ++a) Na[a] = N(a);
    acc.add(rule.weights[q] * J.det, x(0), x(1), Na, nodes.begin(), C::nodes);
  }
}

template <fem::CellType T>
void edgeCell(const mesh::Mesh& mesh, int cell, Accumulator& acc) {
  using C = fem::Cell<T>;
  const auto nodes = mesh.cellNodes(cell);
  const fem::NodeCoords<T> X = coordinatesOf<T>(mesh, cell);
  const auto& rule = fem::edgeRule(2 * C::degree + 4);
  for (int q = 0; q < rule.size(); ++q) {
    const auto& xi = rule.points[q];
    const auto N = C::values(xi);
    const Eigen::Vector2d x = X.transpose() * N;
    const Eigen::Vector2d t = X.transpose() * C::gradients(xi);
    const double w = rule.weights[q] * t.norm();
    double Na[C::nodes];
    for (int a = 0; a < C::nodes; ++a) Na[a] = N(a);
    acc.add(w, x(0), x(1), Na, nodes.begin(), C::nodes);
  }
}

template <fem::CellType T>
void surfaceGaussPoints(const mesh::Mesh& mesh, int cell, bool axisymmetric, CellGaussPoints& g) {
  using C = fem::Cell<T>;
  const fem::NodeCoords<T> X = coordinatesOf<T>(mesh, cell);
  const auto& rule = fem::fullSurfaceRule(T, axisymmetric);
  for (int q = 0; q < rule.size(); ++q) {
    const auto N = C::values(rule.points[q]);
    const auto J = fem::jacobian<T>(X, C::gradients(rule.points[q]));
    g.weights.push_back(rule.weights[q] * J.det);
    for (int a = 0; a < C::nodes; ++a) g.shape.push_back(N(a));
  }
  g.count = rule.size();
  g.nodes = C::nodes;
  g.dimension = 2;
}

template <fem::CellType T>
void edgeGaussPoints(const mesh::Mesh& mesh, int cell, CellGaussPoints& g) {
  using C = fem::Cell<T>;
  const fem::NodeCoords<T> X = coordinatesOf<T>(mesh, cell);
  const auto& rule = fem::fullEdgeRule(T);
  for (int q = 0; q < rule.size(); ++q) {
    const auto N = C::values(rule.points[q]);
    const Eigen::Vector2d t = X.transpose() * C::gradients(rule.points[q]);
    g.weights.push_back(rule.weights[q] * t.norm());
    for (int a = 0; a < C::nodes; ++a) g.shape.push_back(N(a));
  }
  g.count = rule.size();
  g.nodes = C::nodes;
  g.dimension = 1;
}

}  // namespace

CellGaussPoints modelGaussPoints(const mesh::Mesh& mesh, int cell, bool axisymmetric) {
  const fem::CellType t = fem::referenceCell(mesh.cellType(cell), "fields at Gauss points");
  CellGaussPoints g;
  if (fem::cellDimension(t) == 2)
    fem::dispatchSurface(t, [&](auto tag) { surfaceGaussPoints<decltype(tag)::value>(mesh, cell, axisymmetric, g); });
  else
    fem::dispatchEdge(t, [&](auto tag) { edgeGaussPoints<decltype(tag)::value>(mesh, cell, g); });
  const auto nodes = mesh.cellNodes(cell);
  g.xyz.assign(3 * static_cast<std::size_t>(g.count), 0.0);
  for (int q = 0; q < g.count; ++q)
    for (int a = 0; a < g.nodes; ++a) {
      const auto p = mesh.node(nodes[a]);
      for (int d = 0; d < 3; ++d) g.xyz[3 * q + d] += g.shape[q * g.nodes + a] * p(d);
    }
  return g;
}

int modelGaussPointCount(mesh::CellType type, bool axisymmetric) {
  const fem::CellType t = fem::referenceCell(type, "fields at Gauss points");
  return fem::cellDimension(t) == 2 ? fem::fullSurfaceRule(t, axisymmetric).size() : fem::fullEdgeRule(t).size();
}

L2Result l2Norms(const mesh::Mesh& mesh, const std::vector<int>& cells, const NodalValues& field,
                 const std::vector<ExactFunction>& exact) {
  if (!field.values || field.componentCount <= 0) throw Error("L2 norm: no field values");
  if (field.values->size() != static_cast<std::size_t>(mesh.nodeCount()) * field.componentCount)
    throw Error("L2 norm: the field has " + std::to_string(field.values->size()) + " values; expected " +
                std::to_string(mesh.nodeCount()) + " nodes x " + std::to_string(field.componentCount) + " components");
  for (int c : field.components)
    if (c < 0 || c >= field.componentCount) throw Error("L2 norm: component index out of range");
  if (!exact.empty() && exact.size() != field.components.size())
    throw Error("L2 norm: " + std::to_string(exact.size()) + " exact functions for " +
                std::to_string(field.components.size()) + " components");
  if (!field.weights.empty() && field.weights.size() != field.components.size())
    throw Error("L2 norm: " + std::to_string(field.weights.size()) + " weights for " +
                std::to_string(field.components.size()) + " components");
  if (cells.empty()) throw Error("L2 norm: no cell to integrate over");
  Accumulator acc{field, exact};
  int dim = -1;
  for (int cell : cells) {
    const fem::CellType t = fem::referenceCell(mesh.cellType(cell), "L2 norms");
    const int d = fem::cellDimension(t);
    if (dim >= 0 && d != dim)
      throw Error("L2 norm: cells of dimensions 1 and 2 mixed (cell " + mesh.cellName(cell) +
                  "); integrate surfaces and edges separately");
    dim = d;
    if (d == 2) {
      fem::dispatchSurface(t, [&](auto tag) { surfaceCell<decltype(tag)::value>(mesh, cell, acc); });
    } else {
      fem::dispatchEdge(t, [&](auto tag) { edgeCell<decltype(tag)::value>(mesh, cell, acc); });
    }
  }
  L2Result r;
  r.error = std::sqrt(acc.err2);
  r.exact = std::sqrt(acc.exact2);
  r.computed = std::sqrt(acc.comp2);
  r.measure = acc.measure;
  return r;
}

}  // namespace aster::post
