// The stresses and strains a law sees at a plane or axisymmetric point: symmetric 3D
// tensors whose xz and yz components are zero, stored as four tensor components
// xx, yy, zz, xy (zz the out-of-plane or hoop direction).
#pragma once

namespace aster::mechanics {

// a : b, xy counted twice (xy and yx).
inline double contract(const double a[4], const double b[4]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + 2 * a[3] * b[3];
}

}  // namespace aster::mechanics
