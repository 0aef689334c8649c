// DEFORMATION='GDEF_LOG' in the plane element, with ELAS: the Hencky material,
// tau = lambda tr(T) I + 2 mu T (tau the Kirchhoff stress J sigma, T = ln V in the
// current frame). Homogeneous uniaxial stretches (D_PLAN, C_PLAN, AXIS; rotated)
// against that closed form, rigid motions stress free, the element tangent against
// central differences of the internal force, and a law integrated incrementally
// from the history (T_n, tau_n) giving the total response. With von Mises
// plasticity (VMIS_ISOT_LINE): a bar in uniaxial tension and compression against
// the closed form in log space, and the tangent of a plastic step from a plastic
// state against central differences.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "mechanics/log_strain_law.hpp"
#include "mechanics/von_mises_plasticity.hpp"
#include "patch_support.hpp"

using namespace aster;
using namespace aster::mechanics;
using namespace testing_support;

namespace {

constexpr double kYoung = 200.0, kPoisson = 0.3;
const double kLambda = kYoung * kPoisson / ((1 + kPoisson) * (1 - 2 * kPoisson));
const double kMu = kYoung / (2 * (1 + kPoisson));

template <CellType T>
using LogElement = PlaneElement<T, BehaviourLaw>;

template <CellType T>
LogElement<T> hencky(PlaneHypothesis h) {
  return LogElement<T>(std::shared_ptr<const BehaviourLaw>(std::make_shared<IsotropicElasticity>(kYoung, kPoisson, h)),
                       Kinematics::Logarithmic);
}

Eigen::Matrix2d rotation(double theta) {
  Eigen::Matrix2d R;
  R << std::cos(theta), -std::sin(theta), std::sin(theta), std::cos(theta);
  return R;
}

// u = (F - I) X (plus a translation) at every node.
template <CellType T>
typename LogElement<T>::Vector homogeneous(const typename LogElement<T>::Coords& X, const Eigen::Matrix2d& F,
                                           const Eigen::Vector2d& shift = Eigen::Vector2d::Zero()) {
  typename LogElement<T>::Vector u;
  for (int a = 0; a < LogElement<T>::nodes; ++a)
    u.template segment<2>(2 * a) = (F - Eigen::Matrix2d::Identity()) * X.row(a).transpose() + shift;
  return u;
}

// The Cauchy stress of the Hencky material for the principal stretches l1 (along
// the direction theta), l2 and l3 (zz): sigma = tau / J in the principal frame.
Eigen::Vector4d henckyCauchy(double l1, double l2, double l3, double theta) {
  const double t1 = std::log(l1), t2 = std::log(l2), t3 = std::log(l3), J = l1 * l2 * l3;
  const double volume = kLambda * (t1 + t2 + t3);
  const Eigen::Matrix2d R = rotation(theta);
  const Eigen::Matrix2d s =
      R * Eigen::Vector2d(volume + 2 * kMu * t1, volume + 2 * kMu * t2).asDiagonal() * R.transpose() / J;
  return {s(0, 0), s(1, 1), (volume + 2 * kMu * t3) / J, s(0, 1)};
}

template <CellType T>
void expectStresses(const LogElement<T>& element, const typename LogElement<T>::Coords& X,
                    const typename LogElement<T>::Vector& u, const Eigen::Vector4d& cauchy,
                    const Eigen::Vector4d& tau) {
  const int n = element.gaussPointCount(), count = element.internalVariableCount();
  ASSERT_EQ(count, 6);  // ELAS has none; GDEF_LOG's TXX, TYY, TZZ, TXY, TXZ, TYZ
  std::vector<double> s(4 * n), v(n * count), natural(n * count, 0.0);
  ElementHistory history;
  history.variables = natural.data();
  element.gaussStresses(X, u, history, s.data(), v.data(), true);
  const double scale = cauchy.norm();
  for (int q = 0; q < n; ++q) {
    for (int i = 0; i < 4; ++i) {
      EXPECT_NEAR(s[4 * q + i], cauchy(i), 1e-12 * scale) << "point " << q << " component " << i;
      EXPECT_NEAR(v[q * count + i], tau(i), 1e-12 * scale) << "point " << q << " variable " << i;
    }
    EXPECT_EQ(v[q * count + 4], 0.0);
    EXPECT_EQ(v[q * count + 5], 0.0);
  }
}

template <CellType T>
void uniaxialPlaneStrain() {
  SCOPED_TRACE(fem::cellName(T));
  const auto X = distortedCell<T>(7);
  const auto element = hencky<T>(PlaneHypothesis::PlaneStrain);
  for (double l1 : {1.6, 0.55}) {
    // sigma_yy = 0: lambda (ln l1 + ln l2) + 2 mu ln l2 = 0; l3 = 1.
    const double l2 = std::exp(-kLambda / (kLambda + 2 * kMu) * std::log(l1));
    for (double theta : {0.0, 0.7}) {
      // F = R diag(l1, l2): T = diag(ln l1, ln l2) (Lagrangian), tau = R tau_T R^T.
      const Eigen::Matrix2d F = rotation(theta) * Eigen::Vector2d(l1, l2).asDiagonal();
      const Eigen::Vector4d sigma = henckyCauchy(l1, l2, 1.0, theta);
      EXPECT_NEAR(henckyCauchy(l1, l2, 1.0, 0.0)(1), 0.0, 1e-12);
      const Eigen::Vector4d tauT = henckyCauchy(l1, l2, 1.0, 0.0) * (l1 * l2);
      expectStresses<T>(element, X, homogeneous<T>(X, F, Eigen::Vector2d(0.3, -0.2)), sigma, tauT);
    }
  }
}

TEST(GdefLog, UniaxialPlaneStrainQuad4) { uniaxialPlaneStrain<CellType::QUAD4>(); }
TEST(GdefLog, UniaxialPlaneStrainTria6) { uniaxialPlaneStrain<CellType::TRIA6>(); }
TEST(GdefLog, UniaxialPlaneStrainQuad9) { uniaxialPlaneStrain<CellType::QUAD9>(); }

TEST(GdefLog, UniaxialPlaneStrainAxialStressClosedForm) {
  // The same state by hand: ln l2 = -nu/(1-nu) ln l1, tau_xx = E/(1-nu^2) ln l1, sigma = tau / (l1 l2).
  const double l1 = 1.6, t1 = std::log(l1), t2 = -kPoisson / (1 - kPoisson) * t1;
  const double expected = kYoung / (1 - kPoisson * kPoisson) * t1 / (l1 * std::exp(t2));
  EXPECT_NEAR(henckyCauchy(l1, std::exp(t2), 1.0, 0.0)(0), expected, 1e-12 * expected);
  const auto X = distortedCell<CellType::QUAD4>(3);
  const auto element = hencky<CellType::QUAD4>(PlaneHypothesis::PlaneStrain);
  std::vector<double> s(4 * element.gaussPointCount()), v(6 * element.gaussPointCount());
  const Eigen::Matrix2d F = Eigen::Vector2d(l1, std::exp(t2)).asDiagonal();
  std::vector<double> natural(v.size(), 0.0);
  ElementHistory history;
  history.variables = natural.data();
  element.gaussStresses(X, homogeneous<CellType::QUAD4>(X, F), history, s.data(), v.data(), true);
  EXPECT_NEAR(s[0], expected, 1e-12 * expected);
  EXPECT_NEAR(s[1], 0.0, 1e-12 * expected);
  // sigma_zz = lambda (t1 + t2) / J = nu sigma_xx.
  EXPECT_NEAR(s[2], kPoisson * expected, 1e-12 * expected);
}

TEST(GdefLog, UniaxialPlaneStress) {
  // sigma_yy = sigma_zz = 0: l2 = l3 = l1^-nu, tau_xx = E ln l1, J = l1^(1 - 2 nu).
  const auto X = distortedCell<CellType::QUAD8>(11);
  const auto element = hencky<CellType::QUAD8>(PlaneHypothesis::PlaneStress);
  for (double l1 : {1.8, 0.6}) {
    const double l2 = std::pow(l1, -kPoisson), J = std::pow(l1, 1 - 2 * kPoisson), theta = -0.4;
    const Eigen::Matrix2d F = rotation(theta) * Eigen::Vector2d(l1, l2).asDiagonal();
    const double sxx = kYoung * std::log(l1) / J;
    const Eigen::Matrix2d R = rotation(theta);
    const Eigen::Matrix2d s = R * Eigen::Vector2d(sxx, 0.0).asDiagonal() * R.transpose();
    expectStresses<CellType::QUAD8>(element, X, homogeneous<CellType::QUAD8>(X, F),
                                    Eigen::Vector4d(s(0, 0), s(1, 1), 0.0, s(0, 1)),
                                    Eigen::Vector4d(kYoung * std::log(l1), 0, 0, 0));
  }
}

TEST(GdefLog, HomogeneousAxisymmetric) {
  // u_r = (lr - 1) r, u_z = (lz - 1) z: principal stretches lr, lz and the hoop lr.
  auto X = distortedCell<CellType::QUAD4>(5);
  X.col(0).array() += 2.0;  // r > 0
  const auto element = hencky<CellType::QUAD4>(PlaneHypothesis::Axisymmetric);
  const double lr = 1.3, lz = 0.8;
  const Eigen::Vector4d sigma = henckyCauchy(lr, lz, lr, 0.0);
  expectStresses<CellType::QUAD4>(element, X, homogeneous<CellType::QUAD4>(X, Eigen::Vector2d(lr, lz).asDiagonal()),
                                  sigma, sigma * (lr * lz * lr));
}

template <CellType T>
void rigidMotionIsStressFree() {
  SCOPED_TRACE(fem::cellName(T));
  const auto X = distortedCell<T>(3);
  for (auto h : {PlaneHypothesis::PlaneStrain, PlaneHypothesis::PlaneStress}) {
    const auto element = hencky<T>(h);
    typename LogElement<T>::Vector f;
    element.internalForce(X, homogeneous<T>(X, rotation(1.0), Eigen::Vector2d(0.7, -2.1)), &f, nullptr);
    EXPECT_LT(f.norm(), 1e-11);
  }
}

TEST(GdefLog, RigidMotionIsStressFree) {
  rigidMotionIsStressFree<CellType::TRIA3>();
  rigidMotionIsStressFree<CellType::QUAD8>();
}

template <CellType T>
void tangentMatchesDifferences(PlaneHypothesis h) {
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> uni(-1, 1);
  const auto element = hencky<T>(h);
  for (int trial = 0; trial < 3; ++trial) {
    SCOPED_TRACE(std::string(fem::cellName(T)) + " " + planeHypothesisName(h) + " trial " + std::to_string(trial));
    auto X = distortedCell<T>(40 + trial);
    if (h == PlaneHypothesis::Axisymmetric) X.col(0).array() += 2.0;
    typename LogElement<T>::Vector u;
    for (int i = 0; i < LogElement<T>::dofs; ++i) u(i) = 0.15 * uni(rng);
    if (trial == 2) u = homogeneous<T>(X, rotation(0.5));  // rigid: equal eigenvalues, no stress
    typename LogElement<T>::Vector f;
    typename LogElement<T>::Matrix K;
    element.internalForce(X, u, &f, &K);
    const typename LogElement<T>::Matrix D = differenceTangent(element, X, u);
    EXPECT_LT((K - D).norm(), 1e-6 * K.norm());
    EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
  }
}

TEST(GdefLog, TangentMatchesDifferences) {
  for (auto h : {PlaneHypothesis::PlaneStrain, PlaneHypothesis::PlaneStress, PlaneHypothesis::Axisymmetric}) {
    tangentMatchesDifferences<CellType::QUAD4>(h);
    tangentMatchesDifferences<CellType::TRIA6>(h);
    tangentMatchesDifferences<CellType::QUAD8>(h);
  }
}

// Elasticity written incrementally, tau = tau_n + D (T - T_n): it reads the history
// the GDEF_LOG law gives it (T_n from the previous displacement, tau_n from its
// internal variables), so from any accepted state it must give the total response.
class IncrementalElasticity final : public BehaviourLaw {
 public:
  explicit IncrementalElasticity(PlaneHypothesis h) : elastic_(kYoung, kPoisson, h) {}
  PlaneHypothesis hypothesis() const override { return elastic_.hypothesis(); }
  int internalVariableCount() const override { return 1; }  // V1: the number of calls on this state
  void integrate(const LawInput& in, LawOutput<VoigtTangent>& out, bool withTangent) const override {
    const Eigen::Vector4d d(in.strainIncrement(0, 0), in.strainIncrement(1, 1), in.strainIncrementZZ,
                            2 * in.strainIncrement(0, 1));
    const Eigen::Vector4d s = Eigen::Map<const Eigen::Vector4d>(in.previousStress) + elastic_.voigt() * d;
    out.stress << s(kXX), s(kXY), s(kXY), s(kYY);
    out.stressZZ = s(kZZ);
    out.strainZZ = in.strainZZ;
    out.variables[0] = in.previousVariables[0] + 1;
    if (withTangent) out.tangent = elastic_.voigt();
  }

 private:
  IsotropicElasticity elastic_;
};

TEST(GdefLog, IncrementalLawFromHistory) {
  for (auto h : {PlaneHypothesis::PlaneStrain, PlaneHypothesis::Axisymmetric}) {
    SCOPED_TRACE(planeHypothesisName(h));
    using Element = LogElement<CellType::QUAD4>;
    auto X = distortedCell<CellType::QUAD4>(9);
    if (h == PlaneHypothesis::Axisymmetric) X.col(0).array() += 2.0;
    const Element incremental(std::shared_ptr<const BehaviourLaw>(std::make_shared<IncrementalElasticity>(h)),
                              Kinematics::Logarithmic);
    const auto total = hencky<CellType::QUAD4>(h);
    ASSERT_EQ(incremental.internalVariableCount(), 7);  // V1, then TXX ... TYZ
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> uni(-1, 1);
    Element::Vector un, u;
    for (int i = 0; i < Element::dofs; ++i) un(i) = 0.2 * uni(rng);
    for (int i = 0; i < Element::dofs; ++i) u(i) = un(i) + 0.1 * uni(rng);
    const int n = incremental.gaussPointCount();
    // The accepted state at u_n, from the natural state.
    std::vector<double> natural(7 * n, 0.0), vn(7 * n), sn(4 * n), v(7 * n);
    ElementHistory first;
    first.variables = natural.data();
    incremental.gaussStresses(X, un, first, sn.data(), vn.data());
    ElementHistory history;
    history.displacement = un.data();
    history.stress = sn.data();
    history.variables = vn.data();
    Element::Vector f, fTotal;
    Element::Matrix K, KTotal;
    incremental.internalForce(X, u, history, v.data(), &f, &K);
    total.internalForce(X, u, &fTotal, &KTotal);
    EXPECT_LT((f - fTotal).norm(), 1e-11 * fTotal.norm());
    EXPECT_LT((K - KTotal).norm(), 1e-11 * KTotal.norm());
    for (int q = 0; q < n; ++q) EXPECT_EQ(v[7 * q], 2.0);
  }
}

constexpr double kYield = 0.4, kHardening = 20.0;  // SY, D_SIGM_EPSI (ECRO_LINE): yield strain 2e-3

std::shared_ptr<const BehaviourLaw> vonMises(PlaneHypothesis h) {
  return std::make_shared<VonMisesPlasticity>(isotropicLinearParameters(kYoung, kPoisson, kHardening, kYield), h);
}

TEST(GdefLog, PlasticUniaxialPlaneStress) {
  // A bar stretched to l in one step from the natural state: in log space the
  // small-strain uniaxial response at e = ln l (one radial return is exact on this
  // proportional path): |tau| = SY + ET (|e| - SY/E) (ET = D_SIGM_EPSI, the slope in
  // the total strain), p = |e| - |tau|/E; the plastic flow is isochoric, so the
  // lateral log strains are -NU tau/E - sign(e) p/2, and J = l exp(2 lateral).
  using Element = LogElement<CellType::QUAD8>;
  const auto X = distortedCell<CellType::QUAD8>(13);
  const Element element(vonMises(PlaneHypothesis::PlaneStress), Kinematics::Logarithmic);
  const int n = element.gaussPointCount(), count = element.internalVariableCount();
  ASSERT_EQ(count, 8);
  const std::vector<std::string> names = element.law().internalVariableNames();
  const std::vector<std::string> expectedNames = {"EPSPEQ", "INDIPLAS", "TXX", "TYY", "TZZ", "TXY", "TXZ", "TYZ"};
  EXPECT_EQ(names, expectedNames);
  for (double l : {1.3, 0.75}) {
    SCOPED_TRACE("stretch " + std::to_string(l));
    const double e = std::log(l), sign = e > 0 ? 1.0 : -1.0;
    const double tau = sign * (kYield + kHardening * (std::fabs(e) - kYield / kYoung));
    const double p = std::fabs(e) - std::fabs(tau) / kYoung;
    const double lateral = -kPoisson * tau / kYoung - sign * p / 2;
    const double J = l * std::exp(2 * lateral), theta = 0.35;
    const Eigen::Matrix2d R = rotation(theta);
    const Eigen::Matrix2d F = R * Eigen::Vector2d(l, std::exp(lateral)).asDiagonal();
    const Eigen::Matrix2d sigma = R * Eigen::Vector2d(tau / J, 0.0).asDiagonal() * R.transpose();
    std::vector<double> s(4 * n), v(n * count), natural(n * count, 0.0);
    ElementHistory history;
    history.variables = natural.data();
    element.gaussStresses(X, homogeneous<CellType::QUAD8>(X, F), history, s.data(), v.data(), true);
    const double tol = 1e-10 * std::fabs(tau);
    for (int q = 0; q < n; ++q) {
      EXPECT_NEAR(s[4 * q + 0], sigma(0, 0), tol);
      EXPECT_NEAR(s[4 * q + 1], sigma(1, 1), tol);
      EXPECT_NEAR(s[4 * q + 2], 0.0, tol);
      EXPECT_NEAR(s[4 * q + 3], sigma(0, 1), tol);
      const double* vq = v.data() + q * count;
      EXPECT_NEAR(vq[0], p, 1e-10 * p);  // EPSPEQ
      EXPECT_EQ(vq[1], 1.0);             // INDIPLAS
      EXPECT_NEAR(vq[2], tau, tol);      // TXX: tau in the frame of the stretch (T = diag(e, lateral))
      for (int i = 3; i < 8; ++i) EXPECT_NEAR(vq[i], 0.0, tol) << names[i];
    }
  }
}

// A plastic step from a plastic state: the tangent against central differences of
// the internal force from the same history.
template <CellType T>
void plasticTangentMatchesDifferences(PlaneHypothesis h) {
  using Element = LogElement<T>;
  SCOPED_TRACE(std::string(fem::cellName(T)) + " " + planeHypothesisName(h));
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> uni(-1, 1);
  auto X = distortedCell<T>(50);
  if (h == PlaneHypothesis::Axisymmetric) X.col(0).array() += 2.0;
  const Element element(vonMises(h), Kinematics::Logarithmic);
  const int n = element.gaussPointCount(), count = element.internalVariableCount();
  typename Element::Vector un, u;
  for (int i = 0; i < Element::dofs; ++i) un(i) = 0.1 * uni(rng);
  for (int i = 0; i < Element::dofs; ++i) u(i) = 1.05 * un(i) + 0.002 * uni(rng);
  std::vector<double> natural(n * count, 0.0), vn(n * count), sn(4 * n), v(n * count);
  ElementHistory first;
  first.variables = natural.data();
  element.gaussStresses(X, un, first, sn.data(), vn.data());
  ElementHistory history;
  history.displacement = un.data();
  history.stress = sn.data();
  history.variables = vn.data();
  typename Element::Vector f, fp, fm;
  typename Element::Matrix K, D;
  element.internalForce(X, u, history, v.data(), &f, &K);
  int plastic = 0;
  for (int q = 0; q < n; ++q) plastic += v[q * count + 1] == 1.0;
  EXPECT_GT(plastic, 0);
  const double step = 1e-6;
  for (int j = 0; j < Element::dofs; ++j) {
    typename Element::Vector up = u, um = u;
    up(j) += step;
    um(j) -= step;
    element.internalForce(X, up, history, v.data(), &fp, nullptr);
    element.internalForce(X, um, history, v.data(), &fm, nullptr);
    D.col(j) = (fp - fm) / (2 * step);
  }
  EXPECT_LT((K - D).norm(), 1e-6 * K.norm());
}

TEST(GdefLog, PlasticTangentMatchesDifferences) {
  for (auto h : {PlaneHypothesis::PlaneStrain, PlaneHypothesis::PlaneStress, PlaneHypothesis::Axisymmetric}) {
    plasticTangentMatchesDifferences<CellType::QUAD4>(h);
    plasticTangentMatchesDifferences<CellType::TRIA6>(h);
  }
}

TEST(GdefLog, InlinedElasticityRefusesIt) {
  EXPECT_THROW(PlaneElement<CellType::QUAD4>(IsotropicElasticity(kYoung, kPoisson, PlaneHypothesis::PlaneStrain),
                                             Kinematics::Logarithmic),
               Error);
}

TEST(GdefLog, KinematicsName) {
  EXPECT_EQ(kinematicsFromName("GDEF_LOG"), Kinematics::Logarithmic);
  EXPECT_THROW(kinematicsFromName("SIMO_MIEHE"), Error);
}

}  // namespace
