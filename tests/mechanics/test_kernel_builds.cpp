// The AVX2 + FMA build of the element arithmetic against the baseline build:
// the same internal force and tangent to rounding, for every cell and law. The
// other mechanics tests (patch tests, tangents against differences) run on the
// build the CPU picks, so together they cover both.
#include <gtest/gtest.h>

#include <random>

#include "core/error.hpp"
#include "patch_support.hpp"

using namespace aster;
using namespace aster::mechanics;
using namespace testing_support;

namespace {

template <CellType T>
void buildsAgree() {
  if (!kernelBuildAvailable(KernelBuild::Avx2Fma)) GTEST_SKIP() << "no AVX2 + FMA build here (Debug build, not x86-64, or a CPU without them)";
  using E = PlaneElement<T>;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> uni(-1, 1);
  for (auto h : {PlaneHypothesis::PlaneStrain, PlaneHypothesis::PlaneStress})
    for (auto k : {Kinematics::SmallStrain, Kinematics::GreenLagrange}) {
      SCOPED_TRACE(fem::cellName(T));
      const auto X = distortedCell<T>(7);
      E vector(IsotropicElasticity(210e3, 0.3, h), k), baseline = vector;
      EXPECT_EQ(vector.build(), KernelBuild::Avx2Fma);  // the default where the CPU has it
      baseline.setBuild(KernelBuild::Baseline);
      typename E::Vector u;
      for (int i = 0; i < E::dofs; ++i) u(i) = 0.2 * uni(rng);
      typename E::Vector f1, f2;
      typename E::Matrix K1, K2;
      vector.internalForce(X, u, &f1, &K1);
      baseline.internalForce(X, u, &f2, &K2);
      EXPECT_LE((f1 - f2).norm(), 1e-14 * f2.norm());
      EXPECT_LE((K1 - K2).norm(), 1e-14 * K2.norm());
      EXPECT_GT(K2.norm(), 1e3);
      vector.internalForce(X, u, nullptr, &K1);  // either output alone
      EXPECT_LE((K1 - K2).norm(), 1e-14 * K2.norm());
      vector.internalForce(X, u, &f1, nullptr);
      EXPECT_LE((f1 - f2).norm(), 1e-14 * f2.norm());
    }
}

}  // namespace

TEST(KernelBuilds, Tria3) { buildsAgree<CellType::TRIA3>(); }
TEST(KernelBuilds, Tria6) { buildsAgree<CellType::TRIA6>(); }
TEST(KernelBuilds, Quad4) { buildsAgree<CellType::QUAD4>(); }
TEST(KernelBuilds, Quad8) { buildsAgree<CellType::QUAD8>(); }
TEST(KernelBuilds, Quad9) { buildsAgree<CellType::QUAD9>(); }

TEST(KernelBuilds, BaselineIsAlwaysThere) {
  EXPECT_TRUE(kernelBuildAvailable(KernelBuild::Baseline));
  PlaneElement<CellType::QUAD8> e(IsotropicElasticity(1.0, 0.3, PlaneHypothesis::PlaneStrain),
                                  Kinematics::SmallStrain);
  e.setBuild(KernelBuild::Baseline);
  EXPECT_EQ(e.build(), KernelBuild::Baseline);
  if (!kernelBuildAvailable(KernelBuild::Avx2Fma)) {
    EXPECT_THROW(e.setBuild(KernelBuild::Avx2Fma), Error);
  }
}
