// Plane (D_PLAN / C_PLAN) continuum element kernels, per unit thickness,
// templated on the cell type so every per-element array has a fixed size.
//
// Local DOF order is node-major: (ux_1, uy_1, ux_2, uy_2, ...), in the cell's
// node order; node coordinates X are the reference (initial) ones.
//
// PETIT (small strain): eps = sym(grad u), sigma = elasticity(eps);
//   f = int B^T sigma, K = int B^T D B (constant).
// GROT_GDEP (total Lagrangian Saint Venant-Kirchhoff): F = I + grad_X u,
//   E = (F^T F - I)/2, S = elasticity(E) (PK2), P = F S (PK1);
//   f_ai = int P_iJ dN_a/dX_J, K = exact derivative of f:
//   material part int B(F)^T D B(F) + geometric part int (grad N_a . S grad N_b) I.
// Stresses at Gauss points: Cauchy for PETIT; PK2 for GROT_GDEP (what code_aster
// stores in SIEF_ELGA for GROT_GDEP), components SIXX, SIYY, SIZZ, SIXY.
#pragma once
#include <vector>

#include <Eigen/Core>

#include "fem/isoparametric.hpp"
#include "fem/quadrature.hpp"
#include "fem/shape_table.hpp"
#include "mechanics/plane_elasticity.hpp"

namespace aster::mechanics {

using fem::CellType;

// The builds of the element arithmetic (plane_element_arithmetic.hpp): baseline
// x86-64, and AVX2 + FMA (about a third faster), which every element uses when
// the CPU has it. They agree to rounding.
enum class KernelBuild { Baseline, Avx2Fma };
bool kernelBuildAvailable(KernelBuild build);

template <CellType T>
class PlaneElement {
 public:
  using C = fem::Cell<T>;
  static constexpr int nodes = C::nodes;
  static constexpr int dofs = 2 * C::nodes;
  using Coords = fem::NodeCoords<T>;                // nodes x 2
  using Vector = Eigen::Matrix<double, dofs, 1>;
  using Matrix = Eigen::Matrix<double, dofs, dofs>;
  static constexpr int stressComponents = 4;        // SIXX, SIYY, SIZZ, SIXY

  // Full integration (fem::fullSurfaceRule) unless a rule is given.
  PlaneElement(const PlaneElasticity& material, Kinematics kinematics);
  PlaneElement(const PlaneElasticity& material, Kinematics kinematics, const fem::QuadratureRule<2>& rule);

  int gaussPointCount() const { return table_.size(); }
  const PlaneElasticity& material() const { return material_; }
  Kinematics kinematics() const { return kinematics_; }
  KernelBuild build() const { return build_; }
  // Throws aster::Error when the build is not available on this CPU.
  void setBuild(KernelBuild build);

  // Internal force f(u) and tangent K = df/du; either output may be null.
  void internalForce(const Coords& X, const Vector& u, Vector* f, Matrix* K) const;

  // Gauss point stresses, stressComponents values per point, point after point
  // (out has gaussPointCount() * 4 entries).
  void gaussStresses(const Coords& X, const Vector& u, double* out) const;

  // Gauss point reference coordinates (x, y per point) and weight * detJ (one
  // per point), for integrating fields and norms; either output may be null.
  void gaussGeometry(const Coords& X, double* xy, double* weightDet) const;

 private:
  PlaneElasticity material_;
  Kinematics kinematics_;
  fem::ShapeTable<T> table_;
  KernelBuild build_;
};

extern template class PlaneElement<CellType::TRIA3>;
extern template class PlaneElement<CellType::TRIA6>;
extern template class PlaneElement<CellType::QUAD4>;
extern template class PlaneElement<CellType::QUAD8>;
extern template class PlaneElement<CellType::QUAD9>;

}  // namespace aster::mechanics
