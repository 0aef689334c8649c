// The arithmetic of the plane element (see plane_element.hpp for the formulas),
// as functions of the tabulated shapes and the behaviour law. It is compiled twice:
// by plane_element.cpp for baseline x86-64 and by plane_element_avx2.cpp for
// AVX2 + FMA, the build chosen at run time. The functions have internal linkage
// (an anonymous namespace) so that the linker never merges the two builds, and
// the AVX2 entry points are flattened so that no inline function of Eigen, of
// fem/ or of the law is emitted from AVX2 code (tests/simd_symbols.cmake
// checks).
#pragma once
#include <cmath>
#include <type_traits>

#include <Eigen/Core>

#include "fem/isoparametric.hpp"
#include "fem/shape_table.hpp"
#include "mechanics/behaviour_law.hpp"
#include "mechanics/isotropic_elasticity.hpp"
#include "mechanics/modelling.hpp"
#include "mechanics/plane_element.hpp"

namespace aster::mechanics::arithmetic {
namespace {

using fem::CellType;

// Gradient of the shape functions w.r.t. X and weight * detJ at point q.
template <CellType T>
double pointGradients(const fem::ShapeTable<T>& table, const fem::NodeCoords<T>& X, int q,
                      typename fem::Cell<T>::Gradients& G) {
  const fem::Jacobian2 j = fem::jacobian<T>(X, table.gradients(q));
  G.noalias() = table.gradients(q) * j.inverse;
  return table.weight(q) * j.det;
}

// In-plane strain (eps or E) and deformation gradient at a point.
template <CellType T, class Vector>
void strainAt(Kinematics kinematics, const typename fem::Cell<T>::Gradients& G, const Vector& u,
              Eigen::Matrix2d& F, Eigen::Matrix2d& strain) {
  // H_ij = du_i/dX_j = sum_a u_ai G_aj.
  const Eigen::Map<const Eigen::Matrix<double, 2, fem::Cell<T>::nodes>> U(u.data());
  const Eigen::Matrix2d H = U * G;
  if (kinematics == Kinematics::SmallStrain) {
    F.setIdentity();
    strain = 0.5 * (H + H.transpose());
  } else {
    F = Eigen::Matrix2d::Identity() + H;
    strain = 0.5 * (F.transpose() * F - Eigen::Matrix2d::Identity());
  }
}

// The law's response at point q, from the strain there and the element's history.
template <CellType T, class Law>
void integrateLaw(const Law& law, Kinematics kinematics, const typename fem::Cell<T>::Gradients& G,
                  const Eigen::Matrix2d& strain, const ElementHistory& history, int q, double* variables,
                  LawOutput<typename Law::Tangent>& out, bool withTangent) {
  LawInput in;
  in.strain = strain;
  const int count = law.internalVariableCount();
  out.variables = count ? variables + q * count : nullptr;
  if constexpr (Law::kUsesHistory) {
    static constexpr double kNaturalStress[4] = {0, 0, 0, 0};
    Eigen::Matrix2d previous = Eigen::Matrix2d::Zero();
    if (history.displacement) {
      Eigen::Matrix2d Fn;
      const Eigen::Map<const Eigen::Matrix<double, 2 * fem::Cell<T>::nodes, 1>> un(history.displacement);
      strainAt<T>(kinematics, G, un, Fn, previous);
    }
    in.strainIncrement = strain - previous;
    in.previousStress = history.stress ? history.stress + 4 * q : kNaturalStress;
    in.previousVariables = count ? history.variables + q * count : nullptr;
    in.time = history.time;
    in.timeIncrement = history.timeIncrement;
  }
  law.integrate(in, out, withTangent);
}

// Whether the element assembles its whole matrix (the law's tangent is not
// symmetric) instead of one triangle mirrored; the inlined elasticity always mirrors.
template <class Law>
bool assemblesWholeMatrix(const Law& law) {
  if constexpr (std::is_same_v<Law, BehaviourLaw>) return !law.symmetricTangent();
  else return false;
}

// The material stiffness of an isotropic tangent: with g_a the gradient of N_a and
// h_a = F g_a, the 2x2 block of nodes a, b (index notation, i, k in-plane) is
//   K_ab(i,k) += lambda' h_ai h_bk + mu ((F F^T)_ik g_a.g_b + h_bi h_ak) + geo_ab delta_ik,
// geo_ab = g_a . (w S) g_b the geometric term (zero for PETIT). Written for the
// blocks b >= a: a third of the flops of B^T D B with 16 x 3 matrices.
template <int nodes, class Matrix>
void addStiffness(const IsotropicTangent& D, double w, const Eigen::Matrix2d& F,
                  const Eigen::Matrix<double, nodes, 2>& G, const Eigen::Matrix<double, nodes, 2>& GS, Matrix& K,
                  bool /*whole: never, the tangent is symmetric*/ = false) {
  const double lambda = w * D.lambda, mu = w * D.mu;
  const Eigen::Matrix<double, 2, nodes> h = F.lazyProduct(G.transpose());
  const Eigen::Matrix2d FFt = mu * F * F.transpose();
  for (int b = 0; b < nodes; ++b)
    for (int a = 0; a <= b; ++a) {
      const double s = G(a, 0) * G(b, 0) + G(a, 1) * G(b, 1);
      const double geo = GS(a, 0) * G(b, 0) + GS(a, 1) * G(b, 1);
      for (int k = 0; k < 2; ++k)
        for (int i = 0; i < 2; ++i)
          K(2 * a + i, 2 * b + k) += lambda * h(i, a) * h(k, b) + mu * h(i, b) * h(k, a) + FFt(i, k) * s +
                                     (i == k ? geo : 0.0);
    }
}

// Any tangent (Voigt), in the plane: its in-plane part D (xx, yy, xy;
// the zz strain of D_PLAN is fixed, that of C_PLAN condensed by the law):
// K_ab += B_a^T (w D) B_b + geo_ab I, with the variation of the strain for node a,
// direction i (Voigt, 2 E12 last)
//   B_a(:, i) = (F_i1 g_a1, F_i2 g_a2, F_i1 g_a2 + F_i2 g_a1),
// for the blocks b >= a (a symmetric tangent) or, with whole, every block.
template <int nodes, class Matrix>
void addStiffness(const VoigtTangent& tangent, double w, const Eigen::Matrix2d& F,
                  const Eigen::Matrix<double, nodes, 2>& G, const Eigen::Matrix<double, nodes, 2>& GS, Matrix& K,
                  bool whole = false) {
  constexpr int inPlane[3] = {kXX, kYY, kXY};
  Eigen::Matrix3d D;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) D(i, j) = tangent(inPlane[i], inPlane[j]);
  Eigen::Matrix<double, 3, 2 * nodes> B;
  for (int a = 0; a < nodes; ++a)
    for (int i = 0; i < 2; ++i) {
      B(0, 2 * a + i) = F(i, 0) * G(a, 0);
      B(1, 2 * a + i) = F(i, 1) * G(a, 1);
      B(2, 2 * a + i) = F(i, 0) * G(a, 1) + F(i, 1) * G(a, 0);
    }
  const Eigen::Matrix<double, 3, 2 * nodes> DB = (w * D) * B;
  for (int b = 0; b < nodes; ++b)
    for (int a = 0; a < (whole ? nodes : b + 1); ++a) {
      const double geo = GS(a, 0) * G(b, 0) + GS(a, 1) * G(b, 1);
      K.template block<2, 2>(2 * a, 2 * b) +=
          B.template middleCols<2>(2 * a).transpose() * DB.template middleCols<2>(2 * b);
      K(2 * a, 2 * b) += geo;
      K(2 * a + 1, 2 * b + 1) += geo;
    }
}

template <CellType T, class Law, class Vector, class Matrix>
void internalForce(const fem::ShapeTable<T>& table, const Law& law, Kinematics kinematics,
                   const fem::NodeCoords<T>& X, const Vector& u, const ElementHistory& history, double* variables,
                   Vector* f, Matrix* K) {
  constexpr int nodes = fem::Cell<T>::nodes;
  if (f) f->setZero();
  if (K) K->setZero();
  const bool geometric = kinematics == Kinematics::GreenLagrange;
  const bool whole = K && assemblesWholeMatrix(law);
  typename fem::Cell<T>::Gradients G;
  for (int q = 0; q < table.size(); ++q) {
    const double w = pointGradients<T>(table, X, q, G);
    Eigen::Matrix2d F, E;
    strainAt<T>(kinematics, G, u, F, E);
    LawOutput<typename Law::Tangent> response;
    integrateLaw<T>(law, kinematics, G, E, history, q, variables, response, K != nullptr);
    const Eigen::Matrix2d wS = w * response.stress;
    if (f) {
      Eigen::Map<Eigen::Matrix<double, 2, nodes>> fa(f->data());  // column a: f_a, node-major like f
      fa.noalias() += (F * wS).lazyProduct(G.transpose());
    }
    if (K) {
      const Eigen::Matrix<double, nodes, 2> GS = geometric ? Eigen::Matrix<double, nodes, 2>(G * wS)
                                                           : Eigen::Matrix<double, nodes, 2>::Zero();
      addStiffness<nodes>(response.tangent, w, F, G, GS, *K, whole);
    }
  }
  if (K && !whole) K->template triangularView<Eigen::StrictlyLower>() = K->transpose();
}

// The 4 stress values of a point: the law's measure (S in GROT_GDEP), or with
// cauchy in GROT_GDEP the Cauchy stress sigma = F S F^T / J, J = det(F) F_zz, and
// sigma_zz = F_zz^2 S_zz / J (F_zz: 1 in D_PLAN, sqrt(1 + 2 E_zz) in C_PLAN, the
// hoop stretch in AXIS), what code_aster stores in SIEF_ELGA.
template <class Response>
void writeStress(const Response& response, bool cauchy, const Eigen::Matrix2d& F, double Fzz, double* out) {
  if (!cauchy) {
    out[0] = response.stress(0, 0);
    out[1] = response.stress(1, 1);
    out[2] = response.stressZZ;
    out[3] = response.stress(0, 1);
    return;
  }
  const double J = F.determinant() * Fzz;
  const Eigen::Matrix2d sigma = F * response.stress * F.transpose() / J;
  out[0] = sigma(0, 0);
  out[1] = sigma(1, 1);
  out[2] = Fzz * Fzz * response.stressZZ / J;
  out[3] = sigma(0, 1);
}

template <CellType T, class Law, class Vector>
void gaussStresses(const fem::ShapeTable<T>& table, const Law& law, Kinematics kinematics,
                   const fem::NodeCoords<T>& X, const Vector& u, const ElementHistory& history, double* out,
                   double* variables, bool cauchy) {
  typename fem::Cell<T>::Gradients G;
  cauchy = cauchy && kinematics == Kinematics::GreenLagrange;
  for (int q = 0; q < table.size(); ++q) {
    pointGradients<T>(table, X, q, G);
    Eigen::Matrix2d F, E;
    strainAt<T>(kinematics, G, u, F, E);
    LawOutput<typename Law::Tangent> response;
    integrateLaw<T>(law, kinematics, G, E, history, q, variables, response, false);
    // C_PLAN: the law reports E_zz (s_zz = 0); D_PLAN: E_zz = 0.
    writeStress(response, cauchy, F, cauchy ? std::sqrt(1.0 + 2.0 * response.strainZZ) : 1.0, out + 4 * q);
  }
}


// AXIS (r = X, the axis along Y), per radian: every integral is weighted by the
// radius R = sum N_a X_a of the reference point. The hoop (zz) component at a
// point, from the radial displacement u_r = sum N_a u_ax:
//   PETIT: eps_tt = u_r / R;  GROT_GDEP: F_tt = 1 + u_r / R, E_tt = (F_tt^2 - 1) / 2.
// Gauss points are interior to the cell, so R > 0 on a cell with X >= 0 (AFFE_MODELE
// refuses X < 0), nodes on the axis included.
// f_a = int R [F S g_a + S_tt F_tt N_a / R e_r], and K its exact derivative:
//   int R B_a^T D B_b (B with the hoop row F_tt N_a / R on u_ar), the in-plane geometric
//   term, and the hoop geometric term S_tt N_a N_b / R on (u_ar, u_br) (GROT_GDEP).
template <CellType T, class Vector>
void hoopStrainAt(Kinematics kinematics, const typename fem::Cell<T>::Values& N, double R, const Vector& u,
                  double& Ftt, double& strainZZ) {
  double ur = 0;
  for (int a = 0; a < fem::Cell<T>::nodes; ++a) ur += N(a) * u(2 * a);
  if (kinematics == Kinematics::SmallStrain) {
    Ftt = 1.0;
    strainZZ = ur / R;
  } else {
    Ftt = 1.0 + ur / R;
    strainZZ = 0.5 * (Ftt * Ftt - 1.0);
  }
}

// The law's 4-component response at an AXIS point q (any law, through its Voigt
// integrate()), from the strain there and the element's history.
template <CellType T, class Law>
void integrateAxisymmetricLaw(const Law& law, Kinematics kinematics, const typename fem::Cell<T>::Gradients& G,
                              const typename fem::Cell<T>::Values& N, double R, const Eigen::Matrix2d& strain,
                              double strainZZ, const ElementHistory& history, int q, double* variables,
                              LawOutput<VoigtTangent>& out, bool withTangent) {
  LawInput in;
  in.strain = strain;
  in.strainZZ = strainZZ;
  const int count = law.internalVariableCount();
  out.variables = count ? variables + q * count : nullptr;
  static constexpr double kNaturalStress[4] = {0, 0, 0, 0};
  Eigen::Matrix2d previous = Eigen::Matrix2d::Zero();
  double previousZZ = 0;
  if (history.displacement) {
    Eigen::Matrix2d Fn;
    double Fttn;
    const Eigen::Map<const Eigen::Matrix<double, 2 * fem::Cell<T>::nodes, 1>> un(history.displacement);
    strainAt<T>(kinematics, G, un, Fn, previous);
    hoopStrainAt<T>(kinematics, N, R, un, Fttn, previousZZ);
  }
  in.strainIncrement = strain - previous;
  in.strainIncrementZZ = strainZZ - previousZZ;
  in.previousStress = history.stress ? history.stress + 4 * q : kNaturalStress;
  in.previousVariables = count ? history.variables + q * count : nullptr;
  in.time = history.time;
  in.timeIncrement = history.timeIncrement;
  law.integrate(in, out, withTangent);
}

template <CellType T, class Law, class Vector, class Matrix>
void internalForceAxisymmetric(const fem::ShapeTable<T>& table, const Law& law, Kinematics kinematics,
                               const fem::NodeCoords<T>& X, const Vector& u, const ElementHistory& history,
                               double* variables, Vector* f, Matrix* K) {
  constexpr int nodes = fem::Cell<T>::nodes;
  if (f) f->setZero();
  if (K) K->setZero();
  const bool geometric = kinematics == Kinematics::GreenLagrange;
  const bool whole = K && assemblesWholeMatrix(law);
  typename fem::Cell<T>::Gradients G;
  Eigen::Matrix<double, 4, 2 * nodes> B;
  for (int q = 0; q < table.size(); ++q) {
    const double w = pointGradients<T>(table, X, q, G);
    const auto& N = table.values(q);
    const double R = X.col(0).dot(N);
    Eigen::Matrix2d F, E;
    strainAt<T>(kinematics, G, u, F, E);
    double Ftt, Ett;
    hoopStrainAt<T>(kinematics, N, R, u, Ftt, Ett);
    LawOutput<VoigtTangent> response;
    integrateAxisymmetricLaw<T>(law, kinematics, G, N, R, E, Ett, history, q, variables, response, K != nullptr);
    const double wr = w * R;
    const Eigen::Matrix2d wS = wr * response.stress;
    const double hoop = w * response.stressZZ;  // w R S_tt / R
    if (f) {
      Eigen::Map<Eigen::Matrix<double, 2, nodes>> fa(f->data());
      fa.noalias() += (F * wS).lazyProduct(G.transpose());
      for (int a = 0; a < nodes; ++a) (*f)(2 * a) += hoop * Ftt * N(a);
    }
    if (K) {
      for (int a = 0; a < nodes; ++a)
        for (int i = 0; i < 2; ++i) {
          B(kXX, 2 * a + i) = F(i, 0) * G(a, 0);
          B(kYY, 2 * a + i) = F(i, 1) * G(a, 1);
          B(kZZ, 2 * a + i) = i == 0 ? Ftt * N(a) / R : 0.0;
          B(kXY, 2 * a + i) = F(i, 0) * G(a, 1) + F(i, 1) * G(a, 0);
        }
      const Eigen::Matrix<double, 4, 2 * nodes> DB = (wr * response.tangent) * B;
      const Eigen::Matrix<double, nodes, 2> GS = G * wS;
      for (int b = 0; b < nodes; ++b)
        for (int a = 0; a < (whole ? nodes : b + 1); ++a) {
          K->template block<2, 2>(2 * a, 2 * b) +=
              B.template middleCols<2>(2 * a).transpose() * DB.template middleCols<2>(2 * b);
          if (!geometric) continue;
          const double geo = GS(a, 0) * G(b, 0) + GS(a, 1) * G(b, 1);
          (*K)(2 * a, 2 * b) += geo + hoop * N(a) * N(b) / R;
          (*K)(2 * a + 1, 2 * b + 1) += geo;
        }
    }
  }
  if (K && !whole) K->template triangularView<Eigen::StrictlyLower>() = K->transpose();
}

template <CellType T, class Law, class Vector>
void gaussStressesAxisymmetric(const fem::ShapeTable<T>& table, const Law& law, Kinematics kinematics,
                               const fem::NodeCoords<T>& X, const Vector& u, const ElementHistory& history,
                               double* out, double* variables, bool cauchy) {
  typename fem::Cell<T>::Gradients G;
  cauchy = cauchy && kinematics == Kinematics::GreenLagrange;
  for (int q = 0; q < table.size(); ++q) {
    pointGradients<T>(table, X, q, G);
    const auto& N = table.values(q);
    const double R = X.col(0).dot(N);
    Eigen::Matrix2d F, E;
    strainAt<T>(kinematics, G, u, F, E);
    double Ftt, Ett;
    hoopStrainAt<T>(kinematics, N, R, u, Ftt, Ett);
    LawOutput<VoigtTangent> response;
    integrateAxisymmetricLaw<T>(law, kinematics, G, N, R, E, Ett, history, q, variables, response, false);
    writeStress(response, cauchy, F, Ftt, out + 4 * q);
  }
}

}  // namespace
}  // namespace aster::mechanics::arithmetic
