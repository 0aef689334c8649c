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

template <CellType T>
void PlaneElement<T>::internalForce(const Coords& X, const Vector& u, Vector* f, Matrix* K) const {
  if (f) f->setZero();
  if (K) K->setZero();
  const bool geometric = kinematics_ == Kinematics::TotalLagrangianSVK;
  typename C::Gradients G;
  Eigen::Matrix<double, 3, dofs> B;
  for (int q = 0; q < table_.size(); ++q) {
    const double w = pointGradients(X, q, G);
    Eigen::Matrix2d F, E;
    strainAt(G, u, F, E);
    const Eigen::Matrix2d S = material_.stress(E);
    // B maps du to (dE_xx, dE_yy, 2 dE_xy); with F = I it is the small-strain B.
    for (int a = 0; a < nodes; ++a)
      for (int i = 0; i < 2; ++i) {
        B(0, 2 * a + i) = F(i, 0) * G(a, 0);
        B(1, 2 * a + i) = F(i, 1) * G(a, 1);
        B(2, 2 * a + i) = F(i, 0) * G(a, 1) + F(i, 1) * G(a, 0);
      }
    if (f) f->noalias() += B.transpose() * Eigen::Vector3d(w * S(0, 0), w * S(1, 1), w * S(0, 1));
    if (K) {
      // Small fixed-size products: coefficient-based (lazyProduct), not Eigen's blocked GEMM.
      const Eigen::Matrix<double, 3, dofs> DB = material_.voigt().lazyProduct(B);
      const Eigen::Matrix<double, dofs, 3> wBt = w * B.transpose();
      K->noalias() += wBt.lazyProduct(DB);
      if (geometric) {
        const Eigen::Matrix<double, nodes, 2> GS = G.lazyProduct(w * S);
        const Eigen::Matrix<double, nodes, nodes> g = GS.lazyProduct(G.transpose());
        for (int b = 0; b < nodes; ++b)
          for (int a = 0; a < nodes; ++a) {
            (*K)(2 * a, 2 * b) += g(a, b);
            (*K)(2 * a + 1, 2 * b + 1) += g(a, b);
          }
      }
    }
  }
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
