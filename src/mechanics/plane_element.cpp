#include "mechanics/plane_element.hpp"

#include <type_traits>
#include <vector>

#include "core/error.hpp"
#include "mechanics/log_strain_law.hpp"
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

namespace {
// The AVX2 build exists for the inlined law only.
template <class Law>
constexpr bool kHasAvx2Build = std::is_same_v<Law, IsotropicElasticity>;
}  // namespace

template <CellType T, class Law>
PlaneElement<T, Law>::PlaneElement(std::shared_ptr<const Law> law, Kinematics kinematics)
    : PlaneElement(law, kinematics,
                   fem::fullSurfaceRule(T, law && law->hypothesis() == PlaneHypothesis::Axisymmetric)) {}

template <CellType T, class Law>
PlaneElement<T, Law>::PlaneElement(std::shared_ptr<const Law> law, Kinematics kinematics,
                                   const fem::QuadratureRule<2>& rule)
    : law_(std::move(law)),
      kinematics_(kinematics),
      strainMeasure_(kinematics == Kinematics::Logarithmic ? Kinematics::GreenLagrange : kinematics),
      axisymmetric_(law_ && law_->hypothesis() == PlaneHypothesis::Axisymmetric),
      table_(rule),
      build_(KernelBuild::Baseline) {
  if (!law_) throw Error("internal error: a plane element without a behaviour law");
  if (kinematics == Kinematics::Logarithmic) {
    if constexpr (std::is_same_v<Law, BehaviourLaw>)
      law_ = std::make_shared<LogarithmicStrainLaw>(std::move(law_));
    else
      throw Error("internal error: DEFORMATION='GDEF_LOG' runs through the BehaviourLaw element");
  }
  // AXIS runs the baseline 4-component path.
  if (kHasAvx2Build<Law> && !axisymmetric_ && kernelBuildAvailable(KernelBuild::Avx2Fma))
    build_ = KernelBuild::Avx2Fma;
}

template <CellType T, class Law>
void PlaneElement<T, Law>::setBuild(KernelBuild build) {
  if (!kernelBuildAvailable(build) || (build == KernelBuild::Avx2Fma && (!kHasAvx2Build<Law> || axisymmetric_)))
    throw Error("the AVX2 + FMA build of the element kernels is not available here");
  build_ = build;
}

template <CellType T, class Law>
void PlaneElement<T, Law>::internalForce(const Coords& X, const Vector& u, const ElementHistory& history,
                                         double* variables, Vector* f, Matrix* K) const {
  if (axisymmetric_)
    return arithmetic::internalForceAxisymmetric<T>(table_, *law_, strainMeasure_, X, u, history, variables, f, K);
#ifdef ASTER_AVX2_KERNELS
  if constexpr (kHasAvx2Build<Law>)
    if (build_ == KernelBuild::Avx2Fma) return avx2::internalForce<T>(table_, *law_, strainMeasure_, X, u, f, K);
#endif
  arithmetic::internalForce<T>(table_, *law_, strainMeasure_, X, u, history, variables, f, K);
}

template <CellType T, class Law>
void PlaneElement<T, Law>::internalForce(const Coords& X, const Vector& u, Vector* f, Matrix* K) const {
  std::vector<double> natural(table_.size() * internalVariableCount(), 0.0), variables(natural.size());
  ElementHistory history;
  history.variables = natural.data();
  internalForce(X, u, history, variables.data(), f, K);
}

template <CellType T, class Law>
void PlaneElement<T, Law>::gaussStresses(const Coords& X, const Vector& u, const ElementHistory& history, double* out,
                                         double* variables, bool cauchy) const {
  if (axisymmetric_)
    return arithmetic::gaussStressesAxisymmetric<T>(table_, *law_, strainMeasure_, X, u, history, out, variables,
                                                    cauchy);
  arithmetic::gaussStresses<T>(table_, *law_, strainMeasure_, X, u, history, out, variables, cauchy);
}

template <CellType T, class Law>
void PlaneElement<T, Law>::gaussStresses(const Coords& X, const Vector& u, double* out) const {
  std::vector<double> natural(table_.size() * internalVariableCount(), 0.0), variables(natural.size());
  ElementHistory history;
  history.variables = natural.data();
  gaussStresses(X, u, history, out, variables.data());
}

template <CellType T, class Law>
void PlaneElement<T, Law>::gaussGeometry(const Coords& X, double* xy, double* weightDet) const {
  for (int q = 0; q < table_.size(); ++q) {
    const Eigen::Vector2d x = X.transpose() * table_.values(q);
    if (xy) {
      xy[2 * q] = x(0);
      xy[2 * q + 1] = x(1);
    }
    if (weightDet)
      weightDet[q] = table_.weight(q) * fem::jacobian<T>(X, table_.gradients(q)).det * (axisymmetric_ ? x(0) : 1.0);
  }
}

template class PlaneElement<CellType::TRIA3>;
template class PlaneElement<CellType::TRIA6>;
template class PlaneElement<CellType::QUAD4>;
template class PlaneElement<CellType::QUAD8>;
template class PlaneElement<CellType::QUAD9>;
template class PlaneElement<CellType::TRIA3, BehaviourLaw>;
template class PlaneElement<CellType::TRIA6, BehaviourLaw>;
template class PlaneElement<CellType::QUAD4, BehaviourLaw>;
template class PlaneElement<CellType::QUAD8, BehaviourLaw>;
template class PlaneElement<CellType::QUAD9, BehaviourLaw>;

}  // namespace aster::mechanics
