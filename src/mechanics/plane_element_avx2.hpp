// The element's internal force and tangent with isotropic elasticity, built for AVX2 + FMA
// (plane_element_avx2.cpp); PlaneElement calls it when the CPU has both.
#pragma once
#include <Eigen/Core>

#include "fem/isoparametric.hpp"
#include "fem/shape_table.hpp"
#include "mechanics/isotropic_elasticity.hpp"
#include "mechanics/modelling.hpp"

namespace aster::mechanics::avx2 {

template <fem::CellType T>
using Vector = Eigen::Matrix<double, 2 * fem::Cell<T>::nodes, 1>;
template <fem::CellType T>
using Matrix = Eigen::Matrix<double, 2 * fem::Cell<T>::nodes, 2 * fem::Cell<T>::nodes>;

template <fem::CellType T>
void internalForce(const fem::ShapeTable<T>& table, const IsotropicElasticity& law, Kinematics kinematics,
                   const fem::NodeCoords<T>& X, const Vector<T>& u, Vector<T>* f, Matrix<T>* K);

}  // namespace aster::mechanics::avx2
