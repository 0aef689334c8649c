// The elements integrate with code_aster's families (fem::fullSurfaceRule):
//  - TRIA6 has 3 points in D_PLAN and C_PLAN (FPG3), 6 in AXIS (FPG6);
//  - on a straight-sided TRIA6, B is linear, so B^T D B is quadratic and FPG3
//    (degree 2) gives the exact linear-elastic stiffness: the same as a degree-6
//    rule, in every build of the element arithmetic;
//  - the QUAD8 stiffness does not depend on the order of its points (FPG9 is
//    the 3 x 3 Gauss rule): the same as the tensor rule in its own order.
#include <gtest/gtest.h>

#include <memory>

#include "fem/quadrature.hpp"
#include "mechanics/plane_element.hpp"

using namespace aster;
using namespace aster::mechanics;

namespace {

template <CellType T>
typename PlaneElement<T>::Coords affineCell() {
  const auto R = fem::Cell<T>::referenceNodes();
  typename PlaneElement<T>::Coords X;
  for (int a = 0; a < R.rows(); ++a) {
    X(a, 0) = 1.0 + 2.0 * R(a, 0) + 0.7 * R(a, 1);
    X(a, 1) = -0.5 + 0.4 * R(a, 0) + 1.3 * R(a, 1);
  }
  return X;
}

template <CellType T>
void sameStiffness(PlaneHypothesis h, const fem::QuadratureRule<2>& reference) {
  auto law = std::make_shared<const IsotropicElasticity>(210.0, 0.3, h);
  const PlaneElement<T> element(law, Kinematics::SmallStrain);
  const PlaneElement<T> exact(law, Kinematics::SmallStrain, reference);
  const auto X = affineCell<T>();
  const typename PlaneElement<T>::Vector u = PlaneElement<T>::Vector::Zero();
  for (KernelBuild b : {KernelBuild::Baseline, KernelBuild::Avx2Fma}) {
    if (!kernelBuildAvailable(b)) continue;
    PlaneElement<T> e = element;
    e.setBuild(b);
    typename PlaneElement<T>::Matrix K, Kexact;
    e.internalForce(X, u, nullptr, &K);
    exact.internalForce(X, u, nullptr, &Kexact);
    EXPECT_LT((K - Kexact).norm(), 1e-12 * Kexact.norm()) << fem::cellName(T);
  }
}

}  // namespace

TEST(ElementRules, Tria6HasThreePointsInPlaneModelsAndSixInAxis) {
  for (auto h : {PlaneHypothesis::PlaneStrain, PlaneHypothesis::PlaneStress, PlaneHypothesis::Axisymmetric}) {
    const PlaneElement<CellType::TRIA6> e(IsotropicElasticity(210.0, 0.3, h), Kinematics::SmallStrain);
    EXPECT_EQ(e.gaussPointCount(), h == PlaneHypothesis::Axisymmetric ? 6 : 3);
  }
}

TEST(ElementRules, StraightTria6StiffnessIsExactWithThreePoints) {
  sameStiffness<CellType::TRIA6>(PlaneHypothesis::PlaneStrain, fem::gaussTriangle(6));
  sameStiffness<CellType::TRIA6>(PlaneHypothesis::PlaneStress, fem::gaussTriangle(6));
}

TEST(ElementRules, Quad8StiffnessDoesNotDependOnThePointOrder) {
  sameStiffness<CellType::QUAD8>(PlaneHypothesis::PlaneStrain, fem::gaussQuadrangle(3));
  sameStiffness<CellType::QUAD9>(PlaneHypothesis::PlaneStress, fem::gaussQuadrangle(3));
}
