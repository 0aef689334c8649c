#include "mechanics/plane_element.hpp"

#include "core/error.hpp"
#include "mechanics/plane_element_arithmetic.hpp"
#include "mechanics/plane_element_avx2.hpp"

namespace aster::mechanics {

bool kernelBuildAvailable(KernelBuild build) {
  if (build == KernelBuild::Baseline) return true;
#ifdef ASTER_AVX2_KERNELS
  static const bool cpuHasAvx2Fma = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return cpuHasAvx2Fma;
#else
  return false;
#endif
}

template <CellType T>
PlaneElement<T>::PlaneElement(const PlaneElasticity& material, Kinematics kinematics)
    : PlaneElement(material, kinematics, fem::fullSurfaceRule(T)) {}

template <CellType T>
PlaneElement<T>::PlaneElement(const PlaneElasticity& material, Kinematics kinematics,
                              const fem::QuadratureRule<2>& rule)
    : material_(material),
      kinematics_(kinematics),
      table_(rule),
      build_(kernelBuildAvailable(KernelBuild::Avx2Fma) ? KernelBuild::Avx2Fma : KernelBuild::Baseline) {}

template <CellType T>
void PlaneElement<T>::setBuild(KernelBuild build) {
  if (!kernelBuildAvailable(build)) throw Error("the AVX2 + FMA build of the element kernels is not available here");
  build_ = build;
}

template <CellType T>
void PlaneElement<T>::internalForce(const Coords& X, const Vector& u, Vector* f, Matrix* K) const {
#ifdef ASTER_AVX2_KERNELS
  if (build_ == KernelBuild::Avx2Fma) return avx2::internalForce<T>(table_, material_, kinematics_, X, u, f, K);
#endif
  arithmetic::internalForce<T>(table_, material_, kinematics_, X, u, f, K);
}

template <CellType T>
void PlaneElement<T>::gaussStresses(const Coords& X, const Vector& u, double* out) const {
  typename C::Gradients G;
  for (int q = 0; q < table_.size(); ++q) {
    arithmetic::pointGradients<T>(table_, X, q, G);
    Eigen::Matrix2d F, E;
    arithmetic::strainAt<T>(kinematics_, G, u, F, E);
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
