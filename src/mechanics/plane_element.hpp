// Plane (D_PLAN / C_PLAN, per unit thickness) and axisymmetric (AXIS, per
// radian) continuum element kernels, templated on the cell type so every
// per-element array has a fixed size. The law's hypothesis() chooses: AXIS
// elements add the hoop strain and weight every integral by the radius
// (plane_element_arithmetic.hpp), through the law's 4-component integrate().
//
// Local DOF order is node-major: (ux_1, uy_1, ux_2, uy_2, ...), in the cell's
// node order; node coordinates X are the reference (initial) ones.
//
// The element owns the kinematics and loops over the Gauss points; at each the
// behaviour law (behaviour_law.hpp, the template parameter Law) maps the strain
// measure to the stress and the tangent D = dS/dE:
// PETIT (small strain): eps = sym(grad u), sigma = law(eps);
//   f = int B^T sigma, K = int B^T D B.
// GROT_GDEP (total Lagrangian): F = I + grad_X u, E = (F^T F - I)/2,
//   S = law(E) (PK2), P = F S (PK1); with ELAS this is Saint Venant-Kirchhoff.
//   f_ai = int P_iJ dN_a/dX_J, K = exact derivative of f:
//   material part int B(F)^T D B(F) + geometric part int (grad N_a . S grad N_b) I.
// GDEF_LOG: as GROT_GDEP, with the law wrapped in LogarithmicStrainLaw
//   (log_strain_law.hpp), the law of E that integrates the given law on the
//   logarithmic strain T = ln(C) / 2; it adds 6 internal variables (tau, the
//   stress dual to T). Law = BehaviourLaw only (the inlined elasticity has no
//   GDEF_LOG build; element_kernel.cpp routes it).
// Stresses at Gauss points: Cauchy for PETIT; PK2 for GROT_GDEP and GDEF_LOG (the
// law's measure), or on demand Cauchy's sigma = F S F^T / J (what code_aster stores
// in SIEF_ELGA for both); components SIXX, SIYY, SIZZ, SIXY.
#pragma once
#include <memory>
#include <type_traits>
#include <vector>

#include <Eigen/Core>

#include "fem/isoparametric.hpp"
#include "fem/quadrature.hpp"
#include "fem/shape_table.hpp"
#include "mechanics/behaviour_law.hpp"
#include "mechanics/element_history.hpp"
#include "mechanics/isotropic_elasticity.hpp"
#include "mechanics/modelling.hpp"

namespace aster::mechanics {

using fem::CellType;

// The builds of the element arithmetic (plane_element_arithmetic.hpp): baseline
// x86-64, and AVX2 + FMA (about a third faster), which every element uses when
// the CPU has it. They agree to rounding.
enum class KernelBuild { Baseline, Avx2Fma };
bool kernelBuildAvailable(KernelBuild build);

// Law: IsotropicElasticity (inlined, built for AVX2 too) or BehaviourLaw (any
// law, through its virtual integrate()).
template <CellType T, class Law = IsotropicElasticity>
class PlaneElement {
 public:
  using C = fem::Cell<T>;
  static constexpr int nodes = C::nodes;
  static constexpr int dofs = 2 * C::nodes;
  using Coords = fem::NodeCoords<T>;                // nodes x 2
  using Vector = Eigen::Matrix<double, dofs, 1>;
  using Matrix = Eigen::Matrix<double, dofs, dofs>;
  static constexpr int stressComponents = 4;        // SIXX, SIYY, SIZZ, SIXY

  // Full integration (fem::fullSurfaceRule) unless a rule is given. GDEF_LOG:
  // throws aster::Error unless Law is BehaviourLaw.
  PlaneElement(std::shared_ptr<const Law> law, Kinematics kinematics);
  PlaneElement(std::shared_ptr<const Law> law, Kinematics kinematics, const fem::QuadratureRule<2>& rule);
  // A copy of `law`, a Law or a class derived from it.
  template <class Concrete, std::enable_if_t<std::is_base_of_v<Law, Concrete>, int> = 0>
  PlaneElement(const Concrete& law, Kinematics kinematics)
      : PlaneElement(std::shared_ptr<const Law>(std::make_shared<Concrete>(law)), kinematics) {}

  int gaussPointCount() const { return table_.size(); }
  // The law the element runs: under GDEF_LOG the LogarithmicStrainLaw around the given one.
  const Law& law() const { return *law_; }
  int internalVariableCount() const { return law_->internalVariableCount(); }
  Kinematics kinematics() const { return kinematics_; }
  bool axisymmetric() const { return axisymmetric_; }
  KernelBuild build() const { return build_; }
  // Throws aster::Error when the build is not available on this CPU.
  void setBuild(KernelBuild build);

  // Internal force f(u) and tangent K = df/du from the state `history`; either
  // output may be null. variables: the law's new internal variables, point after
  // point (gaussPointCount() * internalVariableCount() entries; null when none).
  void internalForce(const Coords& X, const Vector& u, const ElementHistory& history, double* variables, Vector* f,
                     Matrix* K) const;
  // From the natural state; the new internal variables are dropped.
  void internalForce(const Coords& X, const Vector& u, Vector* f, Matrix* K) const;

  // Gauss point stresses, stressComponents values per point, point after point
  // (out has gaussPointCount() * 4 entries), and the new internal variables as above.
  // The law's measure (S in GROT_GDEP, what the next increment starts from), or
  // with cauchy the Cauchy stress (code_aster's SIEF_ELGA; the same in PETIT).
  void gaussStresses(const Coords& X, const Vector& u, const ElementHistory& history, double* out,
                     double* variables, bool cauchy = false) const;
  // From the natural state.
  void gaussStresses(const Coords& X, const Vector& u, double* out) const;

  // Gauss point reference coordinates (x, y per point) and weight * detJ (one
  // per point; times the radius x in AXIS: per radian), for integrating fields
  // and norms; either output may be null.
  void gaussGeometry(const Coords& X, double* xy, double* weightDet) const;

 private:
  std::shared_ptr<const Law> law_;
  Kinematics kinematics_;
  Kinematics strainMeasure_;  // what law_ takes: GDEF_LOG's law takes E (GreenLagrange)
  bool axisymmetric_;
  fem::ShapeTable<T> table_;
  KernelBuild build_;
};

extern template class PlaneElement<CellType::TRIA3>;
extern template class PlaneElement<CellType::TRIA3, BehaviourLaw>;
extern template class PlaneElement<CellType::TRIA6>;
extern template class PlaneElement<CellType::TRIA6, BehaviourLaw>;
extern template class PlaneElement<CellType::QUAD4>;
extern template class PlaneElement<CellType::QUAD4, BehaviourLaw>;
extern template class PlaneElement<CellType::QUAD8>;
extern template class PlaneElement<CellType::QUAD8, BehaviourLaw>;
extern template class PlaneElement<CellType::QUAD9>;
extern template class PlaneElement<CellType::QUAD9, BehaviourLaw>;

}  // namespace aster::mechanics
