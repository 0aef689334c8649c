// The element arithmetic with the inlined isotropic law (which has neither
// history nor internal variables) compiled with -mavx2 -mfma, and with Eigen's static
// alignment kept at 16 bytes so that the matrices passed in have the layout of
// the baseline build (src/CMakeLists.txt). flatten inlines every Eigen and fem/
// function into these entry points, so no AVX2 copy of a shared inline function
// can reach the baseline code through the linker.
#ifdef ASTER_AVX2_KERNELS
#if !defined(__AVX2__) || !defined(__FMA__)
#error "plane_element_avx2.cpp must be compiled with -mavx2 -mfma (see src/CMakeLists.txt)"
#endif
#include "mechanics/plane_element_avx2.hpp"

#include "mechanics/plane_element_arithmetic.hpp"

namespace aster::mechanics::avx2 {

template <fem::CellType T>
[[gnu::flatten]] void internalForce(const fem::ShapeTable<T>& table, const IsotropicElasticity& law,
                                    Kinematics kinematics, const fem::NodeCoords<T>& X, const Vector<T>& u,
                                    Vector<T>* f, Matrix<T>* K) {
  arithmetic::internalForce<T>(table, law, kinematics, X, u, ElementHistory{}, nullptr, f, K);
}

#define ASTER_INSTANTIATE(T)                                                                                   \
  template void internalForce<fem::CellType::T>(const fem::ShapeTable<fem::CellType::T>&,                     \
                                                const IsotropicElasticity&, Kinematics,                        \
                                                const fem::NodeCoords<fem::CellType::T>&,                      \
                                                const Vector<fem::CellType::T>&, Vector<fem::CellType::T>*,    \
                                                Matrix<fem::CellType::T>*);
ASTER_INSTANTIATE(TRIA3)
ASTER_INSTANTIATE(TRIA6)
ASTER_INSTANTIATE(QUAD4)
ASTER_INSTANTIATE(QUAD8)
ASTER_INSTANTIATE(QUAD9)
#undef ASTER_INSTANTIATE

}  // namespace aster::mechanics::avx2
#endif
