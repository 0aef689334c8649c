// Type erasure over the cell-templated plane element kernels, so the assembly
// loop handles a model mixing TRIA3 ... QUAD9 cells and behaviour laws. One
// kernel object per (cell type, law, kinematics), shared by its cells.
#pragma once
#include <memory>

#include "mechanics/behaviour_law.hpp"
#include "mechanics/modelling.hpp"
#include "mechanics/element_history.hpp"
#include "mesh/cell_type.hpp"

namespace aster::mechanics {

class ElementKernel {
 public:
  virtual ~ElementKernel() = default;
  virtual int nodes() const = 0;
  virtual int gaussPoints() const = 0;
  // The law's internal variables per Gauss point.
  virtual int internalVariables() const = 0;
  // Whether the law integrates from the element's history (else it may be empty).
  virtual bool usesHistory() const = 0;
  // X: node coordinates, nodes x 2 column-major (all x then all y); u: 2*nodes
  // node-major. f, K (column-major 2n x 2n) may be null. variables: the new
  // internal variables, gaussPoints() * internalVariables() (null when none).
  virtual void internalForce(const double* X, const double* u, const ElementHistory& history, double* variables,
                             double* f, double* K) const = 0;
  // 4 values (SIXX, SIYY, SIZZ, SIXY; SIZZ the hoop stress in AXIS) per Gauss point,
  // and the new internal variables. The law's measure (S in GROT_GDEP: the state the
  // next increment starts from), or with cauchy the Cauchy stress (SIEF_ELGA).
  virtual void stresses(const double* X, const double* u, const ElementHistory& history, double* out,
                        double* variables, bool cauchy) const = 0;
  // Gauss point coordinates (x, y per point) and weight*detJ (times x in AXIS: per
  // radian); either may be null.
  virtual void gaussGeometry(const double* X, double* xy, double* weightDet) const = 0;
};

// An IsotropicElasticity law runs the kernels it is inlined into (the AVX2 build
// included; in AXIS the baseline 4-component path); any other law, and any law
// under GDEF_LOG, through its virtual integrate(). The law's hypothesis() makes the element axisymmetric or
// not. Throws aster::Error for a cell type without a plane element.
std::unique_ptr<ElementKernel> makePlaneKernel(mesh::CellType type, std::shared_ptr<const BehaviourLaw> law,
                                               Kinematics kinematics);

}  // namespace aster::mechanics
