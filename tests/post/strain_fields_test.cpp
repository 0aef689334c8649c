// Strains at Gauss points from nodal displacements: an affine displacement
// u = A x gives the uniform linearized strain sym(A) and the Green-Lagrange
// strain sym(A) + A^T A / 2 at every point of every cell type, on distorted
// cells; EPZZ is 0 in plane strain and -nu/(1-nu)(EPXX+EPYY) in plane stress.
// AXIS: u_r = a r, u_z = b z gives EPXX = a, EPYY = b, EPZZ = a (E: x + x^2/2 of
// each); u_r = c gives the hoop strain c / r at each point's radius.
#include <gtest/gtest.h>

#include <vector>

#include "fem/quadrature.hpp"
#include "fem/shape_functions.hpp"
#include "post/strain_fields.hpp"

using namespace aster;
using fem::CellType;

namespace {

template <CellType T>
std::vector<double> distortedNodes() {
  const auto R = fem::Cell<T>::referenceNodes();
  std::vector<double> X;
  for (int a = 0; a < R.rows(); ++a) {
    const double s = R(a, 0), t = R(a, 1);
    // A smooth distortion keeping straight edges: an affine map plus a small shear.
    X.push_back(2.0 + 1.5 * s + 0.3 * t);
    X.push_back(-1.0 + 0.2 * s + 1.1 * t);
  }
  return X;
}

template <CellType T>
void check() {
  const auto X = distortedNodes<T>();
  const double A[2][2] = {{0.02, -0.03}, {0.05, -0.01}};
  std::vector<double> u;
  for (std::size_t a = 0; a < X.size() / 2; ++a) {
    u.push_back(A[0][0] * X[2 * a] + A[0][1] * X[2 * a + 1] + 0.7);
    u.push_back(A[1][0] * X[2 * a] + A[1][1] * X[2 * a + 1] - 0.2);
  }
  const int n = post::strainPointCount(T, false);
  std::vector<double> eps(4 * n), gl(4 * n);
  post::gaussStrains(T, X.data(), u.data(), post::StrainMeasure::Linearized, {true, 0.25}, eps.data());
  post::gaussStrains(T, X.data(), u.data(), post::StrainMeasure::GreenLagrange, {false, 0.25}, gl.data());
  const double exx = A[0][0], eyy = A[1][1], exy = 0.5 * (A[0][1] + A[1][0]);
  // (A^T A)_ij = sum_k A_ki A_kj.
  const double gxx = exx + 0.5 * (A[0][0] * A[0][0] + A[1][0] * A[1][0]);
  const double gyy = eyy + 0.5 * (A[0][1] * A[0][1] + A[1][1] * A[1][1]);
  const double gxy = exy + 0.5 * (A[0][0] * A[0][1] + A[1][0] * A[1][1]);
  for (int q = 0; q < n; ++q) {
    EXPECT_NEAR(eps[4 * q + 0], exx, 1e-14) << fem::cellName(T);
    EXPECT_NEAR(eps[4 * q + 1], eyy, 1e-14);
    EXPECT_NEAR(eps[4 * q + 2], -0.25 / 0.75 * (exx + eyy), 1e-14);
    EXPECT_NEAR(eps[4 * q + 3], exy, 1e-14);
    EXPECT_NEAR(gl[4 * q + 0], gxx, 1e-14);
    EXPECT_NEAR(gl[4 * q + 1], gyy, 1e-14);
    EXPECT_EQ(gl[4 * q + 2], 0.0);
    EXPECT_NEAR(gl[4 * q + 3], gxy, 1e-14);
  }
}

template <CellType T>
void checkAxis() {
  const auto X = distortedNodes<T>();  // r = 2 + 1.5 s + 0.3 t > 0
  const double a = 0.03, b = -0.02, c = 0.01;
  std::vector<double> u, shift;
  for (std::size_t n = 0; n < X.size() / 2; ++n) {
    u.push_back(a * X[2 * n]);
    u.push_back(b * X[2 * n + 1]);
    shift.push_back(c);
    shift.push_back(0.0);
  }
  post::OutOfPlaneStrain axis;
  axis.axisymmetric = true;
  const int n = post::strainPointCount(T, true);
  EXPECT_EQ(n, fem::fullSurfaceRule(T, true).size());
  std::vector<double> eps(4 * n), gl(4 * n), hoop(4 * n), hoopGl(4 * n);
  post::gaussStrains(T, X.data(), u.data(), post::StrainMeasure::Linearized, axis, eps.data());
  post::gaussStrains(T, X.data(), u.data(), post::StrainMeasure::GreenLagrange, axis, gl.data());
  post::gaussStrains(T, X.data(), shift.data(), post::StrainMeasure::Linearized, axis, hoop.data());
  post::gaussStrains(T, X.data(), shift.data(), post::StrainMeasure::GreenLagrange, axis, hoopGl.data());
  const auto& rule = fem::fullSurfaceRule(T, true);
  for (int q = 0; q < n; ++q) {
    EXPECT_NEAR(eps[4 * q + 0], a, 1e-15) << fem::cellName(T);
    EXPECT_NEAR(eps[4 * q + 1], b, 1e-15);
    EXPECT_NEAR(eps[4 * q + 2], a, 1e-15);
    EXPECT_NEAR(eps[4 * q + 3], 0.0, 1e-15);
    EXPECT_NEAR(gl[4 * q + 0], a + a * a / 2, 1e-15);
    EXPECT_NEAR(gl[4 * q + 1], b + b * b / 2, 1e-15);
    EXPECT_NEAR(gl[4 * q + 2], a + a * a / 2, 1e-15);
    EXPECT_NEAR(gl[4 * q + 3], 0.0, 1e-15);
    const double r = 2.0 + 1.5 * rule.points[q](0) + 0.3 * rule.points[q](1);
    EXPECT_NEAR(hoop[4 * q + 0], 0.0, 1e-15);
    EXPECT_NEAR(hoop[4 * q + 2], c / r, 1e-15);
    EXPECT_NEAR(hoopGl[4 * q + 2], ((1 + c / r) * (1 + c / r) - 1) / 2, 1e-15);
  }
}

}  // namespace

TEST(GaussStrains, AxisPatchTria3) { checkAxis<CellType::TRIA3>(); }
TEST(GaussStrains, AxisPatchTria6) { checkAxis<CellType::TRIA6>(); }
TEST(GaussStrains, AxisPatchQuad4) { checkAxis<CellType::QUAD4>(); }
TEST(GaussStrains, AxisPatchQuad8) { checkAxis<CellType::QUAD8>(); }
TEST(GaussStrains, AxisPatchQuad9) { checkAxis<CellType::QUAD9>(); }

TEST(GaussStrains, AffineDisplacementTria3) { check<CellType::TRIA3>(); }
TEST(GaussStrains, AffineDisplacementTria6) { check<CellType::TRIA6>(); }
TEST(GaussStrains, AffineDisplacementQuad4) { check<CellType::QUAD4>(); }
TEST(GaussStrains, AffineDisplacementQuad8) { check<CellType::QUAD8>(); }
TEST(GaussStrains, AffineDisplacementQuad9) { check<CellType::QUAD9>(); }
