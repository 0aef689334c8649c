#include "mechanics/log_strain.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace aster::mechanics {
namespace {

// g(c) = ln(c) / 2 of c = 1 + 2 e.
double g(double e) { return 0.5 * std::log1p(2 * e); }

// g[c_a, c_b] = (ln c_a - ln c_b) / (2 (c_a - c_b)) = atanh(x) / (x (c_a + c_b)),
// x = (c_a - c_b) / (c_a + c_b): no cancellation, 1 / (2 c) at x = 0.
double firstDifference(double ea, double eb) {
  const double sum = 1 + ea + eb;  // (c_a + c_b) / 2
  const double x = (ea - eb) / sum;
  const double x2 = x * x;
  const double h = std::fabs(x) < 1e-4 ? 1 + x2 / 3 + x2 * x2 / 5 : std::atanh(x) / x;
  return h / (2 * sum);
}

// g[c_a, c_b, c_c] for the eigenvalues a, b, c (indices into e, first the
// matrix of the first differences), symmetric in its arguments. Apart from nearly
// equal arguments, the difference of first differences over the widest pair;
// otherwise the Taylor series about the mean m: with d_i = c_i - m (sum zero),
// g[.,.,.] = g2(m)/2 + g4(m)/24 h2(d) + g5(m)/120 h3(d) + O(d^4), gk the k-th derivative
// of g: g2 = -1/(2 m^2), g4 = -3/m^4, g5 = 12/m^5; h2 = sum d^2 / 2, h3 = sum d^3 / 3.
// Either way the relative error stays near 1e-12 (switch at a spread of 1e-3).
double secondDifference(const double e[3], const Eigen::Matrix3d& first, int a, int b, int c) {
  int i[3] = {a, b, c};
  std::sort(i, i + 3, [&](int x, int y) { return e[x] < e[y]; });
  const double lo = e[i[0]], mid = e[i[1]], hi = e[i[2]];
  const double spread = 2 * (hi - lo);  // c_max - c_min
  if (spread > 1e-3 * (1 + 2 * hi)) return (first(i[0], i[1]) - first(i[1], i[2])) / (2 * (lo - hi));
  const double mean = (lo + mid + hi) / 3;
  const double m = 1 + 2 * mean;
  double p2 = 0, p3 = 0;
  for (double ei : {lo, mid, hi}) {
    const double d = 2 * (ei - mean);
    p2 += d * d;
    p3 += d * d * d;
  }
  const double m2 = m * m;
  return -1 / (4 * m2) - p2 / (16 * m2 * m2) + p3 / (30 * m2 * m2 * m);
}

}  // namespace

LogarithmicStrain::LogarithmicStrain(const Eigen::Matrix2d& E, double Ezz) {
  // In-plane eigenvalues m +- r; eigenvector (cos t, sin t) for m + r, t = atan2(2 E12, E11 - E22) / 2.
  const double m = 0.5 * (E(0, 0) + E(1, 1)), h = 0.5 * (E(0, 0) - E(1, 1)), b = 0.5 * (E(0, 1) + E(1, 0));
  const double r = std::hypot(h, b);
  e_[0] = m + r;
  e_[1] = m - r;
  e_[2] = Ezz;
  for (int i = 0; i < 3; ++i) {
    const double c = 1 + 2 * e_[i];
    if (!(c > 0))
      throw Error("DEFORMATION='GDEF_LOG': C = F^T F is not positive definite (an eigenvalue " +
                  std::to_string(c) + "): a singular deformation");
  }
  const double t = 0.5 * std::atan2(b, h), cs = std::cos(t), sn = std::sin(t);
  Q_ << cs, -sn, 0,  //
      sn, cs, 0,     //
      0, 0, 1;
  const Eigen::Vector2d n0(cs, sn), n1(-sn, cs);
  T_ = g(e_[0]) * n0 * n0.transpose() + g(e_[1]) * n1 * n1.transpose();
  Tzz_ = g(e_[2]);
}

Eigen::Matrix3d LogarithmicStrain::eigenbasisVariation(int b) const {
  Eigen::Matrix3d dC = Eigen::Matrix3d::Zero();  // 2 dE for a unit Voigt component b
  switch (b) {
    case 0: dC(0, 0) = 2; break;
    case 1: dC(1, 1) = 2; break;
    case 2: dC(2, 2) = 2; break;
    default: dC(0, 1) = dC(1, 0) = 1; break;  // d(2 E12) = 1
  }
  return Q_.transpose() * dC * Q_;
}

Eigen::Matrix3d LogarithmicStrain::firstDifferences() const {
  Eigen::Matrix3d first;
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) first(i, j) = first(j, i) = firstDifference(e_[i], e_[j]);
  return first;
}

Eigen::Matrix4d LogarithmicStrain::projector() const {
  const Eigen::Matrix3d first = firstDifferences();
  Eigen::Matrix4d P;
  for (int b = 0; b < 4; ++b) {
    const Eigen::Matrix3d dT = Q_ * first.cwiseProduct(eigenbasisVariation(b)) * Q_.transpose();
    P.col(b) << dT(0, 0), dT(1, 1), dT(2, 2), 2 * dT(0, 1);
  }
  return P;
}

Eigen::Matrix4d LogarithmicStrain::stressCurvature(const Eigen::Vector4d& tau) const {
  Eigen::Matrix3d t;
  t << tau(0), tau(3), 0,  //
      tau(3), tau(1), 0,   //
      0, 0, tau(2);
  const Eigen::Matrix3d tt = Q_.transpose() * t * Q_;
  const Eigen::Matrix3d first = firstDifferences();
  double second[3][3][3];
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j) second[i][k][j] = secondDifference(e_, first, i, k, j);
  Eigen::Matrix3d H[4];
  for (int b = 0; b < 4; ++b) H[b] = eigenbasisVariation(b);
  Eigen::Matrix4d M;
  for (int b = 0; b < 4; ++b)
    for (int c = b; c < 4; ++c) {
      double sum = 0;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          if (tt(i, j) == 0) continue;
          for (int k = 0; k < 3; ++k)
            sum += tt(i, j) * second[i][k][j] * (H[b](i, k) * H[c](k, j) + H[c](i, k) * H[b](k, j));
        }
      M(b, c) = M(c, b) = sum;
    }
  return M;
}

}  // namespace aster::mechanics
