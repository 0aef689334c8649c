// GROT_GDEP: rigid motions are stress free; consistent tangents against
// central differences of the internal force; uniaxial SVK stretch by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "patch_support.hpp"

using namespace aster;
using namespace aster::mechanics;
using namespace testing_support;

namespace {

template <CellType T>
void rigidMotion() {
  SCOPED_TRACE(fem::cellName(T));
  using E = PlaneElement<T>;
  const auto X = distortedCell<T>(3);
  const double theta = std::acos(-1.0) / 3;  // 60 degrees
  Eigen::Matrix2d R;
  R << std::cos(theta), -std::sin(theta), std::sin(theta), std::cos(theta);
  typename E::Vector u;
  for (int a = 0; a < E::nodes; ++a)
    u.template segment<2>(2 * a) = (R - Eigen::Matrix2d::Identity()) * X.row(a).transpose() + Eigen::Vector2d(0.7, -2.1);
  for (auto h : {PlaneHypothesis::PlaneStrain, PlaneHypothesis::PlaneStress}) {
    const E element(IsotropicElasticity(1000.0, 0.3, h), Kinematics::GreenLagrange);
    typename E::Vector f;
    element.internalForce(X, u, &f, nullptr);
    EXPECT_LT(f.norm(), 1e-11);
    std::vector<double> s(4 * element.gaussPointCount());
    element.gaussStresses(X, u, s.data());
    for (double v : s) EXPECT_NEAR(v, 0.0, 1e-11);
    // The small-strain element is not rotation invariant: a sanity check that
    // the test would catch a wrong kinematics.
    const E small(IsotropicElasticity(1000.0, 0.3, h), Kinematics::SmallStrain);
    small.internalForce(X, u, &f, nullptr);
    EXPECT_GT(f.norm(), 1.0);
  }
}

template <CellType T>
void tangentMatchesDifferences() {
  using E = PlaneElement<T>;
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> uni(-1, 1);
  for (auto h : {PlaneHypothesis::PlaneStrain, PlaneHypothesis::PlaneStress})
    for (auto k : {Kinematics::SmallStrain, Kinematics::GreenLagrange})
      for (int trial = 0; trial < 3; ++trial) {
        SCOPED_TRACE(std::string(fem::cellName(T)) + " trial " + std::to_string(trial));
        const auto X = distortedCell<T>(100 + trial);
        const E element(IsotropicElasticity(3.0, 0.25, h), k);
        typename E::Vector u;
        for (int i = 0; i < E::dofs; ++i) u(i) = 0.15 * uni(rng);
        typename E::Vector f;
        typename E::Matrix K;
        element.internalForce(X, u, &f, &K);
        EXPECT_LT((K - differenceTangent(element, X, u)).norm(), 1e-6 * K.norm());
        EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());  // hyperelastic: symmetric
      }
}

}  // namespace

TEST(LargeStrain, RigidMotionIsStressFree) {
  rigidMotion<CellType::TRIA3>();
  rigidMotion<CellType::TRIA6>();
  rigidMotion<CellType::QUAD4>();
  rigidMotion<CellType::QUAD8>();
  rigidMotion<CellType::QUAD9>();
}

TEST(Tangent, Tria3) { tangentMatchesDifferences<CellType::TRIA3>(); }
TEST(Tangent, Tria6) { tangentMatchesDifferences<CellType::TRIA6>(); }
TEST(Tangent, Quad4) { tangentMatchesDifferences<CellType::QUAD4>(); }
TEST(Tangent, Quad8) { tangentMatchesDifferences<CellType::QUAD8>(); }
TEST(Tangent, Quad9) { tangentMatchesDifferences<CellType::QUAD9>(); }

// Unit square QUAD4, stretch l in x, lateral contraction m in y chosen so that
// S22 = 0 (lateral face free):
//   E11 = (l^2 - 1)/2, E22 = (m^2 - 1)/2;
//   C_PLAN: E22 = -nu E11, S11 = Young E11;
//   D_PLAN: E22 = -nu/(1-nu) E11, S11 = Young/(1-nu^2) E11, S33 = nu S11.
// The right edge carries the total force P11 * 1 = l S11 in x.
TEST(LargeStrain, UniaxialSaintVenantKirchhoffByHand) {
  const double young = 1.0, nu = 0.3, l = 1.4;
  const double E11 = 0.5 * (l * l - 1);
  struct Case {
    PlaneHypothesis h;
    double E22, S11, S33;
  };
  const Case cases[] = {
      {PlaneHypothesis::PlaneStress, -nu * E11, young * E11, 0.0},
      {PlaneHypothesis::PlaneStrain, -nu / (1 - nu) * E11, young / (1 - nu * nu) * E11,
       nu * young / (1 - nu * nu) * E11},
  };
  for (const auto& c : cases) {
    const double m = std::sqrt(1 + 2 * c.E22);
    fem::NodeCoords<CellType::QUAD4> X;
    X << 0, 0, 1, 0, 1, 1, 0, 1;
    PlaneElement<CellType::QUAD4>::Vector u;
    for (int a = 0; a < 4; ++a) {
      u(2 * a) = (l - 1) * X(a, 0);
      u(2 * a + 1) = (m - 1) * X(a, 1);
    }
    const PlaneElement<CellType::QUAD4> element(IsotropicElasticity(young, nu, c.h), Kinematics::GreenLagrange);
    double s[16];
    element.gaussStresses(X, u, s);
    for (int q = 0; q < 4; ++q) {
      EXPECT_NEAR(s[4 * q + 0], c.S11, 1e-14);
      EXPECT_NEAR(s[4 * q + 1], 0.0, 1e-14);
      EXPECT_NEAR(s[4 * q + 2], c.S33, 1e-14);
      EXPECT_NEAR(s[4 * q + 3], 0.0, 1e-14);
    }
    PlaneElement<CellType::QUAD4>::Vector f;
    element.internalForce(X, u, &f, nullptr);
    EXPECT_NEAR(f(2) + f(4), l * c.S11, 1e-14);   // nodes 2 and 3: the right edge
    EXPECT_NEAR(f(0) + f(6), -l * c.S11, 1e-14);  // left edge: the reaction
    for (int a = 0; a < 4; ++a) EXPECT_NEAR(f(2 * a + 1), 0.0, 1e-14);
  }
}

TEST(IsotropicElasticity, RejectsBadData) {
  EXPECT_THROW(IsotropicElasticity(0.0, 0.3, PlaneHypothesis::PlaneStrain), Error);
  EXPECT_THROW(IsotropicElasticity(1.0, 0.5, PlaneHypothesis::PlaneStrain), Error);
  const IsotropicElasticity m(1.0, 0.3, PlaneHypothesis::PlaneStress);
  EXPECT_NEAR(m.planeLambda(), 0.3 / (1 - 0.09), 1e-15);  // E nu / (1 - nu^2)
}
