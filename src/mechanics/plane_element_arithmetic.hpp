// The arithmetic of the plane element (see plane_element.hpp for the formulas),
// as functions of the tabulated shapes and the material. It is compiled twice:
// by plane_element.cpp for baseline x86-64 and by plane_element_avx2.cpp for
// AVX2 + FMA, the build chosen at run time. The functions have internal linkage
// (an anonymous namespace) so that the linker never merges the two builds, and
// the AVX2 entry points are flattened so that no inline function of Eigen or of
// fem/ is emitted from AVX2 code (tests/mechanics/avx2_symbols.cmake checks).
#pragma once
#include <Eigen/Core>

#include "fem/isoparametric.hpp"
#include "fem/shape_table.hpp"
#include "mechanics/plane_elasticity.hpp"

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

// With g_a the gradient of N_a, h_a = F g_a and the isotropic law S = lambda' tr(E) I + 2 mu E,
// the 2x2 block of nodes a, b of the tangent is (index notation, i, k in-plane)
//   K_ab(i,k) = lambda' h_ai h_bk + mu ((F F^T)_ik g_a.g_b + h_bi h_ak) + (g_a . S g_b) delta_ik,
// the last term (geometric) for large displacements only; and f_a = F S g_a. Written for
// the blocks b >= a, then mirrored: a third of the flops of B^T D B with 16 x 3 matrices.
template <CellType T, class Vector, class Matrix>
void internalForce(const fem::ShapeTable<T>& table, const PlaneElasticity& material, Kinematics kinematics,
                   const fem::NodeCoords<T>& X, const Vector& u, Vector* f, Matrix* K) {
  constexpr int nodes = fem::Cell<T>::nodes;
  if (f) f->setZero();
  if (K) K->setZero();
  const bool geometric = kinematics == Kinematics::TotalLagrangianSVK;
  typename fem::Cell<T>::Gradients G;
  for (int q = 0; q < table.size(); ++q) {
    const double w = pointGradients<T>(table, X, q, G);
    Eigen::Matrix2d F, E;
    strainAt<T>(kinematics, G, u, F, E);
    const Eigen::Matrix2d wS = w * material.stress(E);
    if (f) {
      Eigen::Map<Eigen::Matrix<double, 2, nodes>> fa(f->data());  // column a: f_a, node-major like f
      fa.noalias() += (F * wS).lazyProduct(G.transpose());
    }
    if (K) {
      const double lambda = w * material.planeLambda(), mu = w * material.mu();
      const Eigen::Matrix<double, 2, nodes> h = F.lazyProduct(G.transpose());
      const Eigen::Matrix2d FFt = mu * F * F.transpose();
      const Eigen::Matrix<double, nodes, 2> GS = geometric ? Eigen::Matrix<double, nodes, 2>(G * wS)
                                                           : Eigen::Matrix<double, nodes, 2>::Zero();
      for (int b = 0; b < nodes; ++b)
        for (int a = 0; a <= b; ++a) {
          const double s = G(a, 0) * G(b, 0) + G(a, 1) * G(b, 1);
          const double geo = GS(a, 0) * G(b, 0) + GS(a, 1) * G(b, 1);
          for (int k = 0; k < 2; ++k)
            for (int i = 0; i < 2; ++i)
              (*K)(2 * a + i, 2 * b + k) += lambda * h(i, a) * h(k, b) + mu * h(i, b) * h(k, a) + FFt(i, k) * s +
                                            (i == k ? geo : 0.0);
        }
    }
  }
  if (K) K->template triangularView<Eigen::StrictlyLower>() = K->transpose();
}

}  // namespace
}  // namespace aster::mechanics::arithmetic
