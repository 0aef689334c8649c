#include "post/strain_fields.hpp"

#include "fem/isoparametric.hpp"
#include "fem/quadrature.hpp"

namespace aster::post {
namespace {

// The node coordinates and displacements of a cell (node-major arrays) as matrices.
template <fem::CellType T>
void gatherCell(const double* Xp, const double* up, fem::NodeCoords<T>& X, fem::NodeCoords<T>& u) {
  for (int a = 0; a < fem::Cell<T>::nodes; ++a)
    for (int d = 0; d < 2; ++d) {
      X(a, d) = Xp[2 * a + d];
      u(a, d) = up[2 * a + d];
    }
}

template <fem::CellType T>
void cellStrains(const double* Xp, const double* up, StrainMeasure measure, OutOfPlaneStrain zz, double* out) {
  using C = fem::Cell<T>;
  fem::NodeCoords<T> X;
  fem::NodeCoords<T> u;
  gatherCell<T>(Xp, up, X, u);
  const auto& rule = fem::fullSurfaceRule(T, zz.axisymmetric);
  for (int q = 0; q < rule.size(); ++q) {
    const auto dN = C::gradients(rule.points[q]);
    const auto N = C::values(rule.points[q]);
    const auto j = fem::jacobian<T>(X, dN);
    const auto dNx = fem::physicalGradients<T>(dN, j);
    const Eigen::Matrix2d H = u.transpose() * dNx;  // H_ij = du_i/dx_j
    Eigen::Matrix2d e = 0.5 * (H + H.transpose());
    if (measure == StrainMeasure::GreenLagrange) e += 0.5 * H.transpose() * H;
    double* o = out + q * kStrainComponents;
    o[0] = e(0, 0);
    o[1] = e(1, 1);
    if (zz.axisymmetric) {
      const double hoop = u.col(0).dot(N) / X.col(0).dot(N);  // u_r / r
      o[2] = measure == StrainMeasure::GreenLagrange ? hoop + 0.5 * hoop * hoop : hoop;
    } else {
      o[2] = zz.planeStress ? -zz.nu / (1 - zz.nu) * (e(0, 0) + e(1, 1)) : 0.0;
    }
    o[3] = e(0, 1);
  }
}

template <fem::CellType T>
void cellGradients(const double* Xp, const double* up, bool axisymmetric, double* out) {
  using C = fem::Cell<T>;
  fem::NodeCoords<T> X;
  fem::NodeCoords<T> u;
  gatherCell<T>(Xp, up, X, u);
  const auto& rule = fem::fullSurfaceRule(T, axisymmetric);
  for (int q = 0; q < rule.size(); ++q) {
    const auto dN = C::gradients(rule.points[q]);
    const auto N = C::values(rule.points[q]);
    const auto dNx = fem::physicalGradients<T>(dN, fem::jacobian<T>(X, dN));
    const Eigen::Matrix2d H = u.transpose() * dNx;  // H_ij = du_i/dx_j
    double* o = out + q * kGradientComponents;
    o[0] = 1 + H(0, 0);
    o[1] = H(0, 1);
    o[2] = H(1, 0);
    o[3] = 1 + H(1, 1);
    o[4] = axisymmetric ? 1 + u.col(0).dot(N) / X.col(0).dot(N) : 1.0;
  }
}

}  // namespace

void gaussDeformationGradients(fem::CellType type, const double* X, const double* u, bool axisymmetric,
                               double* out) {
  fem::dispatchSurface(type, [&](auto tag) { cellGradients<decltype(tag)::value>(X, u, axisymmetric, out); });
}

void gaussStrains(fem::CellType type, const double* X, const double* u, StrainMeasure measure, OutOfPlaneStrain zz,
                  double* out) {
  fem::dispatchSurface(type, [&](auto tag) { cellStrains<decltype(tag)::value>(X, u, measure, zz, out); });
}

int strainPointCount(fem::CellType type, bool axisymmetric) {
  return fem::fullSurfaceRule(type, axisymmetric).size();
}

}  // namespace aster::post
