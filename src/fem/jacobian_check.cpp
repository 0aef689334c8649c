#include "fem/jacobian_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "fem/isoparametric.hpp"
#include "fem/mesh_cell_type.hpp"
#include "fem/quadrature.hpp"
#include "fem/shape_functions.hpp"

namespace aster::fem {

namespace {

bool known(mesh::CellType t) {
  switch (t) {
    case mesh::CellType::SEG2:
    case mesh::CellType::SEG3:
    case mesh::CellType::TRIA3:
    case mesh::CellType::TRIA6:
    case mesh::CellType::QUAD4:
    case mesh::CellType::QUAD8:
    case mesh::CellType::QUAD9: return true;
    default: return false;
  }
}

void count(JacobianSigns& s, double det) {
  if (det > 0) ++s.positive;
  else if (det < 0) ++s.negative;
  else ++s.zero;  // also NaN: no orientation at all
  if (!(det >= s.smallest)) s.smallest = det;
}

}  // namespace

JacobianSigns jacobianSigns(const mesh::Mesh& mesh, int cell, bool axisymmetric) {
  JacobianSigns s;
  s.smallest = std::numeric_limits<double>::infinity();
  const mesh::CellType type = mesh.cellType(cell);
  if (!known(type)) return JacobianSigns{};
  const auto nodes = mesh.cellNodes(cell);
  const CellType t = referenceCell(type, "VERI_JACOBIEN");
  auto coordinates = [&](auto& X) {
    for (int a = 0; a < nodes.size(); ++a) {
      const auto x = mesh.node(nodes[a]);
      X(a, 0) = x[0];
      X(a, 1) = x[1];
    }
  };
  if (cellDimension(t) == 2) {
    dispatchSurface(t, [&](auto tag) {
      constexpr CellType T = decltype(tag)::value;
      NodeCoords<T> X;
      coordinates(X);
      const auto& rule = fullSurfaceRule(T, axisymmetric);
      for (int q = 0; q < rule.size(); ++q) count(s, (X.transpose() * Cell<T>::gradients(rule.points[q])).determinant());
    });
  } else {
    dispatchEdge(t, [&](auto tag) {
      constexpr CellType T = decltype(tag)::value;
      NodeCoords<T> X;
      coordinates(X);
      const auto& rule = fullEdgeRule(T);
      for (int q = 0; q < rule.size(); ++q) count(s, (X.transpose() * Cell<T>::gradients(rule.points[q])).norm());
    });
  }
  return s;
}

}  // namespace aster::fem
