// Strains at the model's Gauss points of one surface cell (fem::fullSurfaceRule,
// the points of SIEF_ELGA), from the nodal displacements: EPSI (linearized,
// eps = sym(grad u)) or EPSG (Green-Lagrange, E = (F^T F - I) / 2, F = I + grad u),
// components EPXX, EPYY, EPZZ, EPXY (tensor shear: half the engineering one).
// The out-of-plane strain is the hypothesis's: zero in plane strain; in plane
// stress the one that makes s_zz = 0 with isotropic elasticity,
// EPZZ = -nu / (1 - nu) (EPXX + EPYY); in AXIS (r = X, the axis along Y) the
// hoop strain, u_r / r (EPSI) or ((1 + u_r / r)^2 - 1) / 2 (EPSG), with r and u_r
// interpolated at the point.
#pragma once
#include "fem/cell_type.hpp"

namespace aster::post {

enum class StrainMeasure { Linearized, GreenLagrange };

inline constexpr int kStrainComponents = 4;  // EPXX, EPYY, EPZZ, EPXY

struct OutOfPlaneStrain {
  bool planeStress = false;   // false: plane strain, EPZZ = 0
  double nu = 0.0;            // Poisson's ratio (plane stress only)
  bool axisymmetric = false;  // AXIS: the hoop strain (and AXIS's integration points)
};

// X, u: (x, y) and (ux, uy) per node in the cell's node order; out receives
// kStrainComponents values per Gauss point, point after point.
void gaussStrains(fem::CellType type, const double* X, const double* u, StrainMeasure measure,
                  OutOfPlaneStrain zz, double* out);

// The deformation gradient F = I + grad u at the same points: F11, F12, F21, F22, F33 per
// point (F33 = 1 + u_r / r in AXIS, else 1: plane strain; in plane stress the element's
// law knows F33, not the displacements).
inline constexpr int kGradientComponents = 5;
void gaussDeformationGradients(fem::CellType type, const double* X, const double* u, bool axisymmetric, double* out);

// The number of Gauss points gaussStrains() fills for a cell type (in AXIS when `axisymmetric`).
int strainPointCount(fem::CellType type, bool axisymmetric);

}  // namespace aster::post
