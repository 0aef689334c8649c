// Type erasure over the cell-templated plane element kernels, so the assembly
// loop handles a model mixing TRIA3 ... QUAD9 cells. One kernel object per
// (cell type, material, modelisation, kinematics), shared by its cells.
#pragma once
#include <memory>

#include "mechanics/plane_elasticity.hpp"
#include "mesh/cell_type.hpp"

namespace aster::mechanics {

class ElementKernel {
 public:
  virtual ~ElementKernel() = default;
  virtual int nodes() const = 0;
  virtual int gaussPoints() const = 0;
  // X: node coordinates, nodes x 2 column-major (all x then all y); u: 2*nodes
  // node-major. f, K (column-major 2n x 2n) may be null.
  virtual void internalForce(const double* X, const double* u, double* f, double* K) const = 0;
  // 4 values (SIXX, SIYY, SIZZ, SIXY) per Gauss point.
  virtual void stresses(const double* X, const double* u, double* out) const = 0;
  // Gauss point coordinates (x, y per point) and weight*detJ; either may be null.
  virtual void gaussGeometry(const double* X, double* xy, double* weightDet) const = 0;
};

// Throws aster::Error for a cell type without a plane element.
std::unique_ptr<ElementKernel> makePlaneKernel(mesh::CellType type, const mechanics::PlaneElasticity& material,
                                               mechanics::Kinematics kinematics);

}  // namespace aster::mechanics
