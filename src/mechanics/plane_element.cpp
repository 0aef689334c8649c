#include "mechanics/plane_element.hpp"

namespace aster::mechanics {

template <CellType T>
PlaneElement<T>::PlaneElement(const PlaneElasticity& material, Kinematics kinematics)
    : PlaneElement(material, kinematics, fem::fullSurfaceRule(T)) {}

template <CellType T>
PlaneElement<T>::PlaneElement(const PlaneElasticity& material, Kinematics kinematics,
                              const fem::QuadratureRule<2>& rule)
    : material_(material), kinematics_(kinematics), table_(rule) {}

template <CellType T>
double PlaneElement<T>::pointGradients(const Coords& X, int q, typename C::Gradients& G) const {
  const fem::Jacobian2 j = fem::jacobian<T>(X, table_.gradients(q));
  G.noalias() = table_.gradients(q) * j.inverse;
  return table_.weight(q) * j.det;
}

template <CellType T>
void PlaneElement<T>::strainAt(const typename C::Gradients& G, const Vector& u, Eigen::Matrix2d& F,
                               Eigen::Matrix2d& strain) const {
  // H_ij = du_i/dX_j = sum_a u_ai G_aj.
  const Eigen::Map<const Eigen::Matrix<double, 2, nodes>> U(u.data());
  const Eigen::Matrix2d H = U * G;
  if (kinematics_ == Kinematics::SmallStrain) {
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
template <CellType T>
void PlaneElement<T>::internalForce(const Coords& X, const Vector& u, Vector* f, Matrix* K) const {
  if (f) f->setZero();
  if (K) K->setZero();
  const bool geometric = kinematics_ == Kinematics::TotalLagrangianSVK;
  typename C::Gradients G;
  for (int q = 0; q < table_.size(); ++q) {
    const double w = pointGradients(X, q, G);
    Eigen::Matrix2d F, E;
    strainAt(G, u, F, E);
    const Eigen::Matrix2d wS = w * material_.stress(E);
    if (f) {
      Eigen::Map<Eigen::Matrix<double, 2, nodes>> fa(f->data());  // column a: f_a, node-major like f
      fa.noalias() += (F * wS).lazyProduct(G.transpose());
    }
    if (K) {
      const double lambda = w * material_.planeLambda(), mu = w * material_.mu();
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

template <CellType T>
void PlaneElement<T>::gaussStresses(const Coords& X, const Vector& u, double* out) const {
  typename C::Gradients G;
  for (int q = 0; q < table_.size(); ++q) {
    pointGradients(X, q, G);
    Eigen::Matrix2d F, E;
    strainAt(G, u, F, E);
    const Eigen::Matrix2d S = material_.stress(E);
    out[4 * q + 0] = S(0, 0);
    out[4 * q + 1] = S(1, 1);
    out[4 * q + 2] = material_.outOfPlaneStress(E);
    out[4 * q + 3] = S(0, 1);
  }
}

template <CellType T>
void PlaneElement<T>::gaussGeometry(const Coords& X, double* xy, double* weightDet) const {
  for (int q = 0; q < table_.size(); ++q) {
    if (xy) {
      const Eigen::Vector2d x = X.transpose() * table_.values(q);
      xy[2 * q] = x(0);
      xy[2 * q + 1] = x(1);
    }
    if (weightDet) weightDet[q] = table_.weight(q) * fem::jacobian<T>(X, table_.gradients(q)).det;
  }
}

template class PlaneElement<CellType::TRIA3>;
template class PlaneElement<CellType::TRIA6>;
template class PlaneElement<CellType::QUAD4>;
template class PlaneElement<CellType::QUAD8>;
template class PlaneElement<CellType::QUAD9>;

}  // namespace aster::mechanics
