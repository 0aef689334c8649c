// Test helpers: small distorted meshes of each surface cell type and a
// reference assembly loop (independent of the mesh module).
#pragma once
#include <map>
#include <random>
#include <vector>

#include <Eigen/Core>

#include "fem/assembly_pattern.hpp"
#include "mechanics/plane_element.hpp"

namespace testing_support {

using aster::fem::CellType;

struct Patch {
  std::vector<Eigen::Vector2d> nodes;
  std::vector<std::vector<int>> cells;
  std::vector<bool> boundary;
};

// An n x n grid over [0, 2] x [0, 1.5] with perturbed interior nodes, split into
// triangles for TRIA3/TRIA6, with mid-nodes (perturbed inside) for quadratic cells.
inline Patch makePatch(CellType type, int n, unsigned seed) {
  std::mt19937 rng(seed);
  const double L = 2.0, H = 1.5, hx = L / n, hy = H / n;
  std::uniform_real_distribution<double> u(-1, 1);
  Patch p;
  auto onBoundary = [&](const Eigen::Vector2d& x) {
    return std::abs(x(0)) < 1e-12 || std::abs(x(0) - L) < 1e-12 || std::abs(x(1)) < 1e-12 ||
           std::abs(x(1) - H) < 1e-12;
  };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      Eigen::Vector2d x(i * hx, j * hy);
      if (!onBoundary(x)) x += Eigen::Vector2d(0.25 * hx * u(rng), 0.25 * hy * u(rng));
      p.nodes.push_back(x);
    }
  std::map<std::pair<int, int>, int> mids;
  auto mid = [&](int a, int b) {
    const auto key = std::make_pair(std::min(a, b), std::max(a, b));
    auto it = mids.find(key);
    if (it != mids.end()) return it->second;
    Eigen::Vector2d x = 0.5 * (p.nodes[a] + p.nodes[b]);
    if (!onBoundary(x)) x += Eigen::Vector2d(0.05 * hx * u(rng), 0.05 * hy * u(rng));
    p.nodes.push_back(x);
    mids[key] = static_cast<int>(p.nodes.size()) - 1;
    return mids[key];
  };
  const bool quadratic = type == CellType::TRIA6 || type == CellType::QUAD8 || type == CellType::QUAD9;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      std::vector<std::vector<int>> corners;
      if (type == CellType::TRIA3 || type == CellType::TRIA6)
        corners = {{a, b, c}, {a, c, d}};
      else
        corners = {{a, b, c, d}};
      for (auto cell : corners) {
        if (quadratic) {
          const int m = static_cast<int>(cell.size());
          for (int k = 0; k < m; ++k) cell.push_back(mid(cell[k], cell[(k + 1) % m]));
        }
        if (type == CellType::QUAD9) {
          Eigen::Vector2d x = Eigen::Vector2d::Zero();
          for (int k = 0; k < 8; ++k) x += p.nodes[cell[k]] / 8;
          p.nodes.push_back(x + Eigen::Vector2d(0.05 * hx * u(rng), 0.05 * hy * u(rng)));
          cell.push_back(static_cast<int>(p.nodes.size()) - 1);
        }
        p.cells.push_back(cell);
      }
    }
  for (const auto& x : p.nodes) p.boundary.push_back(onBoundary(x));
  return p;
}

template <CellType T>
typename aster::mechanics::PlaneElement<T>::Coords cellCoords(const Patch& p, int c) {
  typename aster::mechanics::PlaneElement<T>::Coords X;
  for (int a = 0; a < aster::fem::Cell<T>::nodes; ++a) X.row(a) = p.nodes[p.cells[c][a]].transpose();
  return X;
}

// K(U) and f_int(U) assembled over the patch (2 DOFs per node, node-major).
template <CellType T>
void assemble(const Patch& p, const aster::mechanics::PlaneElement<T>& element,
              const aster::fem::AssemblyPattern& pattern, const Eigen::VectorXd& U, aster::linalg::SparseMatrix& K,
              Eigen::VectorXd& F) {
  using E = aster::mechanics::PlaneElement<T>;
  K = pattern.newMatrix();
  F = Eigen::VectorXd::Zero(pattern.dofCount());
  typename E::Vector ue, fe;
  typename E::Matrix Ke;
  for (int c = 0; c < static_cast<int>(p.cells.size()); ++c) {
    pattern.gather(c, U.data(), ue.data());
    element.internalForce(cellCoords<T>(p, c), ue, &fe, &Ke);
    pattern.addMatrix(c, Ke, K);
    pattern.addVector(c, fe, F);
  }
}

// One distorted cell: an affine image of the reference cell with every node moved.
template <CellType T>
typename aster::mechanics::PlaneElement<T>::Coords distortedCell(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::Matrix2d A;
  A << 1.3, 0.3, -0.2, 0.9;
  const auto R = aster::fem::Cell<T>::referenceNodes();
  typename aster::mechanics::PlaneElement<T>::Coords X;
  for (int a = 0; a < R.rows(); ++a)
    X.row(a) = (A * R.row(a).transpose() + Eigen::Vector2d(0.5, -1) + 0.06 * Eigen::Vector2d(u(rng), u(rng)))
                   .transpose();
  return X;
}

// The element's tangent by central differences of its internal force (step 1e-6:
// truncation and rounding errors both about 1e-10 relative for these cells).
template <class Element>
typename Element::Matrix differenceTangent(const Element& element, const typename Element::Coords& X,
                                           const typename Element::Vector& u) {
  const double step = 1e-6;
  typename Element::Matrix K;
  typename Element::Vector fp, fm;
  for (int j = 0; j < Element::dofs; ++j) {
    typename Element::Vector up = u, um = u;
    up(j) += step;
    um(j) -= step;
    element.internalForce(X, up, &fp, nullptr);
    element.internalForce(X, um, &fm, nullptr);
    K.col(j) = (fp - fm) / (2 * step);
  }
  return K;
}

}  // namespace testing_support
