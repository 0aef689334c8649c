// Patch tests: a linear displacement imposed on the boundary of a distorted
// patch is reproduced exactly inside (PETIT), with the exact constant stress;
// a homogeneous large deformation leaves no internal force on interior nodes
// (GROT_GDEP).
#include <gtest/gtest.h>

#include <Eigen/SparseLU>

#include "patch_support.hpp"

using namespace aster;
using namespace aster::mechanics;
using namespace testing_support;

namespace {

// Exact linear field u = c + A X.
const Eigen::Vector2d kC(0.01, -0.02);
Eigen::Matrix2d gradient() {
  Eigen::Matrix2d A;
  A << 1e-3, 2e-3, -0.5e-3, 1.5e-3;
  return A;
}

template <CellType T>
void smallStrainPatch(PlaneHypothesis hypothesis) {
  SCOPED_TRACE(std::string(fem::cellName(T)) + (hypothesis == PlaneHypothesis::PlaneStrain ? " D_PLAN" : " C_PLAN"));
  const Patch p = makePatch(T, 3, 11);
  const int nn = static_cast<int>(p.nodes.size());
  const fem::DofMap map(nn, 2);
  fem::ElementDofs dofs;
  dofs.addCells(p.cells, map, 2);
  const fem::AssemblyPattern pattern(map.dofCount(), dofs);
  const IsotropicElasticity material(200.0, 0.3, hypothesis);
  const PlaneElement<T> element(material, Kinematics::SmallStrain);

  const Eigen::Matrix2d A = gradient();
  Eigen::VectorXd exact(map.dofCount()), Up = Eigen::VectorXd::Zero(map.dofCount());
  std::vector<int> freeDofs;
  for (int n = 0; n < nn; ++n) {
    const Eigen::Vector2d u = kC + A * p.nodes[n];
    exact.segment<2>(2 * n) = u;
    if (p.boundary[n]) Up.segment<2>(2 * n) = u;
    else freeDofs.insert(freeDofs.end(), {2 * n, 2 * n + 1});
  }
  linalg::SparseMatrix K;
  Eigen::VectorXd F;
  assemble<T>(p, element, pattern, Eigen::VectorXd::Zero(map.dofCount()), K, F);
  // Free block: K_ff u_f = -K_fp u_p.
  Eigen::SparseMatrix<double> S(static_cast<int>(freeDofs.size()), map.dofCount());
  for (std::size_t k = 0; k < freeDofs.size(); ++k) S.insert(static_cast<int>(k), freeDofs[k]) = 1;
  const Eigen::SparseMatrix<double> Kff = S * K * S.transpose();
  const Eigen::VectorXd rhs = -(S * (K * Up));
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(Kff);
  ASSERT_EQ(lu.info(), Eigen::Success);
  const Eigen::VectorXd uf = lu.solve(rhs);
  const Eigen::VectorXd U = Up + S.transpose() * uf;
  EXPECT_LT((U - exact).cwiseAbs().maxCoeff(), 1e-12 * exact.cwiseAbs().maxCoeff());

  // Stresses: sigma = lambda' tr(eps) I + 2 mu eps, by hand with E, nu.
  const double E = 200, nu = 0.3;
  const Eigen::Matrix2d eps = 0.5 * (A + A.transpose());
  double sxx, syy, szz, sxy = E / (1 + nu) * eps(0, 1);
  if (hypothesis == PlaneHypothesis::PlaneStrain) {
    const double c = E / ((1 + nu) * (1 - 2 * nu));
    sxx = c * ((1 - nu) * eps(0, 0) + nu * eps(1, 1));
    syy = c * ((1 - nu) * eps(1, 1) + nu * eps(0, 0));
    szz = nu * (sxx + syy);
  } else {
    const double c = E / (1 - nu * nu);
    sxx = c * (eps(0, 0) + nu * eps(1, 1));
    syy = c * (eps(1, 1) + nu * eps(0, 0));
    szz = 0;
  }
  std::vector<double> s(4 * element.gaussPointCount());
  for (int c = 0; c < static_cast<int>(p.cells.size()); ++c) {
    typename PlaneElement<T>::Vector ue;
    pattern.gather(c, U.data(), ue.data());
    element.gaussStresses(cellCoords<T>(p, c), ue, s.data());
    for (int q = 0; q < element.gaussPointCount(); ++q) {
      EXPECT_NEAR(s[4 * q + 0], sxx, 1e-12 * std::abs(sxx));
      EXPECT_NEAR(s[4 * q + 1], syy, 1e-12 * std::abs(sxx));
      EXPECT_NEAR(s[4 * q + 2], szz, 1e-12 * std::abs(sxx));
      EXPECT_NEAR(s[4 * q + 3], sxy, 1e-12 * std::abs(sxx));
    }
  }
  // The patch area from the Gauss weights: 2 x 1.5.
  double area = 0;
  std::vector<double> wd(element.gaussPointCount()), xy(2 * element.gaussPointCount());
  for (int c = 0; c < static_cast<int>(p.cells.size()); ++c) {
    element.gaussGeometry(cellCoords<T>(p, c), xy.data(), wd.data());
    for (double w : wd) area += w;
  }
  EXPECT_NEAR(area, 3.0, 1e-13);
}

template <CellType T>
void homogeneousLargeStrainPatch(PlaneHypothesis hypothesis) {
  SCOPED_TRACE(fem::cellName(T));
  const Patch p = makePatch(T, 3, 5);
  const int nn = static_cast<int>(p.nodes.size());
  const fem::DofMap map(nn, 2);
  fem::ElementDofs dofs;
  dofs.addCells(p.cells, map, 2);
  const fem::AssemblyPattern pattern(map.dofCount(), dofs);
  const PlaneElement<T> element(IsotropicElasticity(1.0, 0.3, hypothesis), Kinematics::GreenLagrange);
  Eigen::Matrix2d Fh;
  Fh << 1.3, 0.4, -0.2, 0.8;
  Eigen::VectorXd U(map.dofCount());
  for (int n = 0; n < nn; ++n) U.segment<2>(2 * n) = (Fh - Eigen::Matrix2d::Identity()) * p.nodes[n];
  linalg::SparseMatrix K;
  Eigen::VectorXd F;
  assemble<T>(p, element, pattern, U, K, F);
  double largest = 0;
  for (int n = 0; n < nn; ++n) {
    largest = std::max(largest, F.segment<2>(2 * n).norm());
    if (!p.boundary[n]) {
      EXPECT_LT(F.segment<2>(2 * n).norm(), 1e-13) << "node " << n;
    }
  }
  EXPECT_GT(largest, 1e-3);  // the boundary does carry the load
}

}  // namespace

TEST(PatchTest, SmallStrainTria3) {
  smallStrainPatch<CellType::TRIA3>(PlaneHypothesis::PlaneStrain);
  smallStrainPatch<CellType::TRIA3>(PlaneHypothesis::PlaneStress);
}
TEST(PatchTest, SmallStrainTria6) {
  smallStrainPatch<CellType::TRIA6>(PlaneHypothesis::PlaneStrain);
  smallStrainPatch<CellType::TRIA6>(PlaneHypothesis::PlaneStress);
}
TEST(PatchTest, SmallStrainQuad4) {
  smallStrainPatch<CellType::QUAD4>(PlaneHypothesis::PlaneStrain);
  smallStrainPatch<CellType::QUAD4>(PlaneHypothesis::PlaneStress);
}
TEST(PatchTest, SmallStrainQuad8) {
  smallStrainPatch<CellType::QUAD8>(PlaneHypothesis::PlaneStrain);
  smallStrainPatch<CellType::QUAD8>(PlaneHypothesis::PlaneStress);
}
TEST(PatchTest, SmallStrainQuad9) {
  smallStrainPatch<CellType::QUAD9>(PlaneHypothesis::PlaneStrain);
  smallStrainPatch<CellType::QUAD9>(PlaneHypothesis::PlaneStress);
}
TEST(PatchTest, HomogeneousLargeStrainAllCells) {
  for (auto h : {PlaneHypothesis::PlaneStrain, PlaneHypothesis::PlaneStress}) {
    homogeneousLargeStrainPatch<CellType::TRIA3>(h);
    homogeneousLargeStrainPatch<CellType::TRIA6>(h);
    homogeneousLargeStrainPatch<CellType::QUAD4>(h);
    homogeneousLargeStrainPatch<CellType::QUAD8>(h);
    homogeneousLargeStrainPatch<CellType::QUAD9>(h);
  }
}
