// AXIS (r = X, the axis along Y, per radian) and C_PLAN in GROT_GDEP:
//  - the AXIS element's tangent (PETIT, GROT_GDEP with the hoop geometric term)
//    against central differences of its internal force, inlined-law and generic paths;
//  - the AXIS patch test: u_r = a r + c0, u_z = b z + c1 imposed on the boundary
//    of a distorted patch touching the axis (nodes at r = 0) is reproduced inside,
//    with the uniform stress (s_rr = s_tt = lambda (2a + b) + 2 mu a,
//    s_zz = lambda (2a + b) + 2 mu b) at every Gauss point (c0 = 0: u_r = 0 on the
//    axis), and the reactions per radian sum, by hand, to int s.n r ds on each side;
//  - the r-weighted loads by hand, and the AXIS follower pressure's tangent;
//  - C_PLAN GROT_GDEP: S_zz = 0 at every Gauss point, the in-plane S of Saint
//    Venant-Kirchhoff with E_zz = -lambda/(lambda + 2 mu) tr E (from S_zz = 0), and
//    the tangent of the generic (4x4 condensed) path against differences.
#include <gtest/gtest.h>

#include <Eigen/SparseLU>
#include <cmath>
#include <random>

#include "mechanics/loads.hpp"
#include "patch_support.hpp"

using namespace aster;
using namespace aster::mechanics;
using namespace testing_support;

namespace {

// A distorted cell moved to X in [0.6, 3.5] (off the axis).
template <CellType T>
typename PlaneElement<T>::Coords offAxisCell(unsigned seed) {
  auto X = distortedCell<T>(seed);
  X.col(0).array() += 2.0;
  return X;
}

template <CellType T, class Law>
void axisTangentMatchesDifferences() {
  using E = PlaneElement<T, Law>;
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> uni(-1, 1);
  for (auto k : {Kinematics::SmallStrain, Kinematics::GreenLagrange})
    for (int trial = 0; trial < 3; ++trial) {
      SCOPED_TRACE(std::string(fem::cellName(T)) + (k == Kinematics::SmallStrain ? " PETIT" : " GROT_GDEP") +
                   " trial " + std::to_string(trial));
      const auto X = offAxisCell<T>(200 + trial);
      const E element(IsotropicElasticity(3.0, 0.3, PlaneHypothesis::Axisymmetric), k);
      EXPECT_TRUE(element.axisymmetric());
      EXPECT_EQ(element.build(), KernelBuild::Baseline);
      typename E::Vector u, f;
      for (int i = 0; i < E::dofs; ++i) u(i) = 0.15 * uni(rng);
      typename E::Matrix K;
      element.internalForce(X, u, &f, &K);
      EXPECT_LT((K - differenceTangent(element, X, u)).norm(), 1e-6 * K.norm());
      EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
    }
}

TEST(Axisymmetric, TangentMatchesDifferences) {
  axisTangentMatchesDifferences<CellType::TRIA3, IsotropicElasticity>();
  axisTangentMatchesDifferences<CellType::TRIA6, IsotropicElasticity>();
  axisTangentMatchesDifferences<CellType::QUAD4, IsotropicElasticity>();
  axisTangentMatchesDifferences<CellType::QUAD8, IsotropicElasticity>();
  axisTangentMatchesDifferences<CellType::QUAD9, IsotropicElasticity>();
  axisTangentMatchesDifferences<CellType::QUAD8, BehaviourLaw>();
  axisTangentMatchesDifferences<CellType::TRIA3, BehaviourLaw>();
}

// The hoop term by hand: a uniform radial expansion u = a X of a QUAD4 [1, 2] x [0, 1]
// (PETIT) has e_rr = e_tt = a, e_zz = 0: s_rr = s_tt = 2 (lambda + mu) a,
// s_zz = 2 lambda a; GROT_GDEP: F_rr = F_tt = 1 + a, E_rr = E_tt = ((1 + a)^2 - 1)/2.
TEST(Axisymmetric, RadialExpansionByHand) {
  const double young = 10.0, nu = 0.25, a = 0.1;
  const double lambda = young * nu / ((1 + nu) * (1 - 2 * nu)), mu = young / (2 * (1 + nu));
  fem::NodeCoords<CellType::QUAD4> X;
  X << 1, 0, 2, 0, 2, 1, 1, 1;
  PlaneElement<CellType::QUAD4>::Vector u;
  for (int n = 0; n < 4; ++n) u.segment<2>(2 * n) << a * X(n, 0), 0.0;
  for (auto k : {Kinematics::SmallStrain, Kinematics::GreenLagrange}) {
    const double e = k == Kinematics::SmallStrain ? a : 0.5 * ((1 + a) * (1 + a) - 1);
    const PlaneElement<CellType::QUAD4> element(IsotropicElasticity(young, nu, PlaneHypothesis::Axisymmetric), k);
    double s[16];
    element.gaussStresses(X, u, s);
    for (int q = 0; q < 4; ++q) {
      EXPECT_NEAR(s[4 * q + 0], 2 * (lambda + mu) * e, 1e-13);
      EXPECT_NEAR(s[4 * q + 1], 2 * lambda * e, 1e-13);
      EXPECT_NEAR(s[4 * q + 2], 2 * (lambda + mu) * e, 1e-13);
      EXPECT_NEAR(s[4 * q + 3], 0.0, 1e-13);
    }
    // Cauchy (SIEF_ELGA): F = diag(1 + a, 1) and F_tt = 1 + a in GROT_GDEP, J = (1 + a)^2:
    // sigma_rr = S_rr, sigma_zz = S_zz / (1 + a)^2, sigma_tt = S_tt; PETIT: the same as S.
    const double J = k == Kinematics::SmallStrain ? 1.0 : (1 + a) * (1 + a);
    ElementHistory history;
    element.gaussStresses(X, u, history, s, nullptr, true);
    for (int q = 0; q < 4; ++q) {
      EXPECT_NEAR(s[4 * q + 0], 2 * (lambda + mu) * e, 1e-13);
      EXPECT_NEAR(s[4 * q + 1], 2 * lambda * e / J, 1e-13);
      EXPECT_NEAR(s[4 * q + 2], 2 * (lambda + mu) * e, 1e-13);
      EXPECT_NEAR(s[4 * q + 3], 0.0, 1e-13);
    }
    // Per radian: the x forces sum to int S_tt F_tt dA = S_tt F_tt (area 1); the
    // right edge (r = 2) carries int P_rr r dz = 2 P_rr, P_rr = F_rr S_rr.
    PlaneElement<CellType::QUAD4>::Vector f;
    element.internalForce(X, u, &f, nullptr);
    const double F = k == Kinematics::SmallStrain ? 1.0 : 1 + a, S = 2 * (lambda + mu) * e;
    EXPECT_NEAR(f(0) + f(2) + f(4) + f(6), S * F, 1e-12);
    // The weights are per radian: int r dA = 1.5.
    double w[4], sum = 0;
    element.gaussGeometry(X, nullptr, w);
    for (double v : w) sum += v;
    EXPECT_NEAR(sum, 1.5, 1e-14);
  }
}

template <CellType T>
void axisPatch() {
  SCOPED_TRACE(fem::cellName(T));
  const Patch p = makePatch(T, 3, 13);  // [0, 2] x [0, 1.5]: the left side is on the axis
  const int nn = static_cast<int>(p.nodes.size());
  const fem::DofMap map(nn, 2);
  fem::ElementDofs dofs;
  dofs.addCells(p.cells, map, 2);
  const fem::AssemblyPattern pattern(map.dofCount(), dofs);
  const double young = 200.0, nu = 0.3, a = 1e-3, b = -2e-3, c1 = 0.01;
  const double lambda = young * nu / ((1 + nu) * (1 - 2 * nu)), mu = young / (2 * (1 + nu));
  const PlaneElement<T> element(IsotropicElasticity(young, nu, PlaneHypothesis::Axisymmetric),
                                Kinematics::SmallStrain);
  Eigen::VectorXd exact(map.dofCount()), Up = Eigen::VectorXd::Zero(map.dofCount());
  std::vector<int> freeDofs;
  for (int n = 0; n < nn; ++n) {
    const Eigen::Vector2d u(a * p.nodes[n](0), b * p.nodes[n](1) + c1);
    exact.segment<2>(2 * n) = u;
    if (p.boundary[n]) Up.segment<2>(2 * n) = u;
    else freeDofs.insert(freeDofs.end(), {2 * n, 2 * n + 1});
  }
  linalg::SparseMatrix K;
  Eigen::VectorXd F;
  assemble<T>(p, element, pattern, Eigen::VectorXd::Zero(map.dofCount()), K, F);
  Eigen::SparseMatrix<double> S(static_cast<int>(freeDofs.size()), map.dofCount());
  for (std::size_t k = 0; k < freeDofs.size(); ++k) S.insert(static_cast<int>(k), freeDofs[k]) = 1;
  const Eigen::SparseMatrix<double> Kff = S * K * S.transpose();
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(Kff);
  ASSERT_EQ(lu.info(), Eigen::Success);
  const Eigen::VectorXd U = Up + S.transpose() * lu.solve(Eigen::VectorXd(-(S * (K * Up))));
  EXPECT_LT((U - exact).cwiseAbs().maxCoeff(), 1e-12 * exact.cwiseAbs().maxCoeff());

  const double srr = lambda * (2 * a + b) + 2 * mu * a, szz = lambda * (2 * a + b) + 2 * mu * b;
  std::vector<double> s(4 * element.gaussPointCount());
  for (int c = 0; c < static_cast<int>(p.cells.size()); ++c) {
    typename PlaneElement<T>::Vector ue;
    pattern.gather(c, U.data(), ue.data());
    element.gaussStresses(cellCoords<T>(p, c), ue, s.data());
    for (int q = 0; q < element.gaussPointCount(); ++q) {
      EXPECT_NEAR(s[4 * q + 0], srr, 1e-12 * std::abs(srr));
      EXPECT_NEAR(s[4 * q + 1], szz, 1e-12 * std::abs(srr));
      EXPECT_NEAR(s[4 * q + 2], srr, 1e-12 * std::abs(srr));  // s_tt = s_rr
      EXPECT_NEAR(s[4 * q + 3], 0.0, 1e-12 * std::abs(srr));
    }
  }
  // Reactions per radian (the internal forces at U; zero inside): on r = 2,
  // sum f_r = s_rr * 2 * 1.5; on the axis r = 0, sum f_r = 0; on z = 0 and z = 1.5,
  // sum f_z = -/+ s_zz int_0^2 r dr = -/+ 2 s_zz.
  Eigen::VectorXd R;
  assemble<T>(p, element, pattern, U, K, R);
  double right = 0, axis = 0, bottom = 0, top = 0;
  for (int n = 0; n < nn; ++n) {
    const Eigen::Vector2d& x = p.nodes[n];
    if (!p.boundary[n]) {
      EXPECT_LT(R.segment<2>(2 * n).norm(), 1e-12 * std::abs(srr)) << "interior node " << n;
      continue;
    }
    if (std::abs(x(0) - 2) < 1e-12) right += R(2 * n);
    if (std::abs(x(0)) < 1e-12) axis += R(2 * n);
    if (std::abs(x(1)) < 1e-12) bottom += R(2 * n + 1);
    if (std::abs(x(1) - 1.5) < 1e-12) top += R(2 * n + 1);
  }
  EXPECT_NEAR(right, 3 * srr, 1e-10 * std::abs(srr));
  EXPECT_NEAR(axis, 0.0, 1e-10 * std::abs(srr));
  EXPECT_NEAR(bottom, -2 * szz, 1e-10 * std::abs(srr));
  EXPECT_NEAR(top, 2 * szz, 1e-10 * std::abs(srr));
}

TEST(Axisymmetric, PatchTria3) { axisPatch<CellType::TRIA3>(); }
TEST(Axisymmetric, PatchTria6) { axisPatch<CellType::TRIA6>(); }
TEST(Axisymmetric, PatchQuad4) { axisPatch<CellType::QUAD4>(); }
TEST(Axisymmetric, PatchQuad8) { axisPatch<CellType::QUAD8>(); }
TEST(Axisymmetric, PatchQuad9) { axisPatch<CellType::QUAD9>(); }

// Loads per radian by hand: a traction (0, 1) on the radial SEG2 from r = 1 to 3:
// f_1 = int_1^3 (3 - r)/2 r dr = 5/3, f_2 = int_1^3 (r - 1)/2 r dr = 7/3; a body
// force (1, 0) on the QUAD4 [1, 2] x [0, 1]: sum f_x = int r dA = 3/2.
TEST(Axisymmetric, LoadsArePerRadian) {
  fem::EdgeCoords<CellType::SEG2> E;
  E << 1, 0, 3, 0;
  const auto f = deadEdgeTraction<CellType::SEG2>(E, [](const Eigen::Vector2d&) { return Eigen::Vector2d(0, 1); },
                                                  true);
  EXPECT_NEAR(f(1), 5.0 / 3, 1e-14);
  EXPECT_NEAR(f(3), 7.0 / 3, 1e-14);
  EXPECT_NEAR(f(0) + f(2), 0.0, 1e-14);
  fem::NodeCoords<CellType::QUAD4> X;
  X << 1, 0, 2, 0, 2, 1, 1, 1;
  const auto b = bodyForce<CellType::QUAD4>(X, [](const Eigen::Vector2d&) { return Eigen::Vector2d(1, 0); }, true);
  EXPECT_NEAR(b(0) + b(2) + b(4) + b(6), 1.5, 1e-14);
  // A pressure p = 3 on the edge r = 2, z from 0 to 1 (walked counterclockwise
  // around a section on its left: outward normal +r): -p * 2 * 1 per radian on r.
  fem::EdgeCoords<CellType::SEG3> V;
  V << 2, 0, 2, 1, 2, 0.5;
  EdgeVector<CellType::SEG3> fp;
  followerPressure<CellType::SEG3>(V, EdgeVector<CellType::SEG3>::Zero(), [](const Eigen::Vector2d&) { return 3.0; },
                                   &fp, nullptr, true);
  EXPECT_NEAR(fp(0) + fp(2) + fp(4), -6.0, 1e-14);
}

template <CellType T>
void axisPressureStiffness() {
  SCOPED_TRACE(fem::cellName(T));
  constexpr int n = fem::Cell<T>::nodes;
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> uni(-1, 1);
  fem::EdgeCoords<T> X;
  X.row(0) << 1.0, 0.1;
  X.row(1) << 2.0, -0.1;
  if (n == 3) X.row(2) << 1.5, 0.15;
  auto p = [](const Eigen::Vector2d& x) { return 2.0 + x(0) * x(0) - x(1); };
  for (int trial = 0; trial < 3; ++trial) {
    EdgeVector<T> u, f, fp, fm;
    for (int i = 0; i < 2 * n; ++i) u(i) = 0.2 * uni(rng);
    EdgeMatrix<T> K, Kfd;
    followerPressure<T>(X, u, p, &f, &K, true);
    const double h = 1e-6;
    for (int j = 0; j < 2 * n; ++j) {
      EdgeVector<T> up = u, um = u;
      up(j) += h;
      um(j) -= h;
      followerPressure<T>(X, up, p, &fp, nullptr, true);
      followerPressure<T>(X, um, p, &fm, nullptr, true);
      Kfd.col(j) = (fp - fm) / (2 * h);
    }
    EXPECT_LT((K - Kfd).norm(), 1e-8 * K.norm());
  }
}

TEST(Axisymmetric, FollowerPressureStiffnessMatchesDifferences) {
  axisPressureStiffness<CellType::SEG2>();
  axisPressureStiffness<CellType::SEG3>();
}

// C_PLAN, GROT_GDEP, a homogeneous deformation F of a distorted cell: E = (F^T F - I)/2
// everywhere; with S_zz = lambda (tr E + E_zz) + 2 mu E_zz = 0 solved for E_zz,
// S = lambda (tr E + E_zz) I + 2 mu E in the plane.
template <CellType T, class Law>
void planeStressLargeStrain() {
  SCOPED_TRACE(fem::cellName(T));
  using E = PlaneElement<T, Law>;
  const double young = 5.0, nu = 0.3;
  const double lambda = young * nu / ((1 + nu) * (1 - 2 * nu)), mu = young / (2 * (1 + nu));
  const E element(IsotropicElasticity(young, nu, PlaneHypothesis::PlaneStress), Kinematics::GreenLagrange);
  const auto X = distortedCell<T>(31);
  Eigen::Matrix2d F;
  F << 1.2, 0.3, -0.1, 0.85;
  typename E::Vector u;
  for (int a = 0; a < E::nodes; ++a)
    u.template segment<2>(2 * a) = (F - Eigen::Matrix2d::Identity()) * X.row(a).transpose();
  const Eigen::Matrix2d G = 0.5 * (F.transpose() * F - Eigen::Matrix2d::Identity());
  const double Ezz = -lambda / (lambda + 2 * mu) * G.trace();
  EXPECT_NEAR(lambda * (G.trace() + Ezz) + 2 * mu * Ezz, 0.0, 1e-14);
  const Eigen::Matrix2d S = lambda * (G.trace() + Ezz) * Eigen::Matrix2d::Identity() + 2 * mu * G;
  std::vector<double> s(4 * element.gaussPointCount());
  element.gaussStresses(X, u, s.data());
  for (int q = 0; q < element.gaussPointCount(); ++q) {
    EXPECT_NEAR(s[4 * q + 0], S(0, 0), 1e-13);
    EXPECT_NEAR(s[4 * q + 1], S(1, 1), 1e-13);
    EXPECT_EQ(s[4 * q + 2], 0.0);
    EXPECT_NEAR(s[4 * q + 3], S(0, 1), 1e-13);
  }
  // SIEF_ELGA: the Cauchy stress F S F^T / J, J = det(F) F_zz with F_zz = sqrt(1 + 2 E_zz)
  // the thickness stretch; its zz component stays 0.
  const double Fzz = std::sqrt(1 + 2 * Ezz);
  const Eigen::Matrix2d sigma = F * S * F.transpose() / (F.determinant() * Fzz);
  std::vector<double> natural(element.gaussPointCount() * element.internalVariableCount() + 1, 0.0);
  ElementHistory history;
  history.variables = natural.data();
  element.gaussStresses(X, u, history, s.data(), natural.data(), true);
  for (int q = 0; q < element.gaussPointCount(); ++q) {
    EXPECT_NEAR(s[4 * q + 0], sigma(0, 0), 1e-13);
    EXPECT_NEAR(s[4 * q + 1], sigma(1, 1), 1e-13);
    EXPECT_EQ(s[4 * q + 2], 0.0);
    EXPECT_NEAR(s[4 * q + 3], sigma(0, 1), 1e-13);
  }
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> uni(-1, 1);
  for (int i = 0; i < E::dofs; ++i) u(i) += 0.05 * uni(rng);
  typename E::Vector f;
  typename E::Matrix K;
  element.internalForce(X, u, &f, &K);
  EXPECT_LT((K - differenceTangent(element, X, u)).norm(), 1e-6 * K.norm());
  element.gaussStresses(X, u, s.data());
  for (int q = 0; q < element.gaussPointCount(); ++q) EXPECT_EQ(s[4 * q + 2], 0.0);
}

TEST(PlaneStress, LargeStrainClosedFormAndTangent) {
  planeStressLargeStrain<CellType::TRIA3, IsotropicElasticity>();
  planeStressLargeStrain<CellType::TRIA6, IsotropicElasticity>();
  planeStressLargeStrain<CellType::QUAD4, IsotropicElasticity>();
  planeStressLargeStrain<CellType::QUAD8, IsotropicElasticity>();
  planeStressLargeStrain<CellType::QUAD9, IsotropicElasticity>();
  planeStressLargeStrain<CellType::QUAD8, BehaviourLaw>();
  planeStressLargeStrain<CellType::TRIA6, BehaviourLaw>();
}

// The 4-component law: D_PLAN's s_zz = nu (s_xx + s_yy) (e_zz = 0); C_PLAN reports
// the e_zz of s_zz = 0, -nu/(1 - nu) (e_xx + e_yy); AXIS reads the given e_zz.
TEST(IsotropicElasticity, FourComponents) {
  const double young = 7.0, nu = 0.2;
  LawInput in;
  in.strain << 0.01, 0.004, 0.004, -0.02;
  LawOutput<VoigtTangent> out;
  IsotropicElasticity(young, nu, PlaneHypothesis::PlaneStrain).integrate(in, out, true);
  EXPECT_NEAR(out.stressZZ, nu * (out.stress(0, 0) + out.stress(1, 1)), 1e-15);
  IsotropicElasticity(young, nu, PlaneHypothesis::PlaneStress).integrate(in, out, true);
  EXPECT_EQ(out.stressZZ, 0.0);
  EXPECT_NEAR(out.strainZZ, -nu / (1 - nu) * (0.01 - 0.02), 1e-16);
  EXPECT_EQ(out.tangent.row(kZZ).norm() + out.tangent.col(kZZ).norm(), 0.0);
  in.strainZZ = 0.003;
  const IsotropicElasticity axis(young, nu, PlaneHypothesis::Axisymmetric);
  axis.integrate(in, out, true);
  // Hooke in 3D: e_zz = (s_zz - nu (s_xx + s_yy)) / E.
  EXPECT_NEAR((out.stressZZ - nu * (out.stress(0, 0) + out.stress(1, 1))) / young, 0.003, 1e-15);
  EXPECT_NEAR((out.stress(0, 0) - nu * (out.stress(1, 1) + out.stressZZ)) / young, 0.01, 1e-15);
  // The tangent is the derivative: one column by the linearity of the law.
  LawOutput<VoigtTangent> moved;
  LawInput step = in;
  step.strainZZ += 1.0;
  axis.integrate(step, moved, false);
  EXPECT_NEAR(moved.stress(0, 0) - out.stress(0, 0), out.tangent(kXX, kZZ), 1e-13);
  EXPECT_NEAR(moved.stressZZ - out.stressZZ, out.tangent(kZZ, kZZ), 1e-13);
}

}  // namespace
