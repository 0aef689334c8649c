// Fixtures shared by the CONTINUE contact tests (test_continue.cpp and
// test_smoothed_normal.cpp): a gently curved line, slave cells along it, and the
// statuses of a cell's contact points.
#pragma once
#include <random>
#include <vector>

#include "contact/continue_formulation.hpp"

namespace aster::contact::testing {

// y = parabola(x): the curved masters and slaves lie near it.
inline double parabola(double X) { return -0.05 * (X - 0.5) * (X - 0.5); }

inline std::vector<PointStatus> statuses(const ContinueCellTerms& t) {
  std::vector<PointStatus> s;
  for (const auto& p : t.points) s.push_back(p.status);
  return s;
}

// A slave cell along y ~ 0 from x0 to x1 (walked left to right: normal -Y), its
// nodes on the parabola moved by up to `noise`.
inline SlaveCell slaveAlong(fem::CellType type, double x0, double x1, std::mt19937& gen, double noise) {
  std::uniform_real_distribution<double> u(-1, 1);
  SlaveCell s;
  s.type = type;
  s.reference.row(0) << x0, 0;
  s.reference.row(1) << x1, 0;
  s.reference.row(2) << 0.5 * (x0 + x1), 0;
  const int ns = type == fem::CellType::SEG3 ? 3 : 2;
  for (int a = 0; a < ns; ++a) {
    const double X = s.reference(a, 0) + noise * u(gen);
    s.current.row(a) << X, parabola(X) + noise * u(gen);
  }
  return s;
}

}  // namespace aster::contact::testing
