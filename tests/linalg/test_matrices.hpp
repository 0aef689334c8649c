// Small test systems with known properties, built from their definitions.
#pragma once
#include <Eigen/SparseCore>
#include <cmath>
#include <vector>

#include "linalg/linear_solver.hpp"

namespace aster::linalg::testing {

using Triplets = std::vector<Eigen::Triplet<double>>;

inline SparseMatrix fromTriplets(int n, const Triplets& t) {
  SparseMatrix A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  return A;
}

// 5-point Laplacian on an m x m grid of interior nodes (Dirichlet boundary): SPD.
inline void laplacian2d(int m, Triplets& t, double diagonalShift = 0.0) {
  auto id = [m](int i, int j) { return i * m + j; };
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      t.emplace_back(id(i, j), id(i, j), 4.0 + diagonalShift);
      if (i > 0) t.emplace_back(id(i, j), id(i - 1, j), -1.0);
      if (i + 1 < m) t.emplace_back(id(i, j), id(i + 1, j), -1.0);
      if (j > 0) t.emplace_back(id(i, j), id(i, j - 1), -1.0);
      if (j + 1 < m) t.emplace_back(id(i, j), id(i, j + 1), -1.0);
    }
}

inline SparseMatrix laplacian2d(int m, double diagonalShift = 0.0) {
  Triplets t;
  laplacian2d(m, t, diagonalShift);
  return fromTriplets(m * m, t);
}

// Convection-diffusion on an m x m grid (upwind convection c): unsymmetric, and nonsingular
// as an irreducibly diagonally dominant matrix (rows sum to 0 inside, > 0 next to the boundary).
inline SparseMatrix convectionDiffusion(int m, double c) {
  auto id = [m](int i, int j) { return i * m + j; };
  Triplets t;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      t.emplace_back(id(i, j), id(i, j), 4.0 + c);
      if (i > 0) t.emplace_back(id(i, j), id(i - 1, j), -1.0 - c);
      if (i + 1 < m) t.emplace_back(id(i, j), id(i + 1, j), -1.0);
      if (j > 0) t.emplace_back(id(i, j), id(i, j - 1), -1.0);
      if (j + 1 < m) t.emplace_back(id(i, j), id(i, j + 1), -1.0);
    }
  return fromTriplets(m * m, t);
}

// Saddle point [K B^T; B 0]: K the m x m grid Laplacian, B ties pairs of unknowns
// (u_a - u_b = g), as Lagrange multipliers of contact or linear relations do.
inline SparseMatrix saddlePoint(int m, int constraints) {
  Triplets t;
  laplacian2d(m, t);
  const int n = m * m;
  for (int c = 0; c < constraints; ++c) {
    const int a = (7 * c + 3) % n, b = (13 * c + 11) % n;
    const int row = n + c;
    t.emplace_back(row, a, 1.0);
    t.emplace_back(a, row, 1.0);
    t.emplace_back(row, b, -2.0);
    t.emplace_back(b, row, -2.0);
  }
  return fromTriplets(n + constraints, t);
}

// A known solution with entries of various signs and sizes.
inline Eigen::VectorXd knownSolution(int n) {
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i) x[i] = std::sin(0.37 * i + 0.1) + 0.01 * (i % 7) - 0.5;
  return x;
}

inline double relativeResidual(const SparseMatrix& A, const Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  return (A * x - b).norm() / b.norm();
}

}  // namespace aster::linalg::testing
