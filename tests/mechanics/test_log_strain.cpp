// The logarithmic strain T = ln(C)/2 of GDEF_LOG (mechanics/log_strain.hpp): T
// against the closed form of a diagonal and of a rotated stretch, P = dT/dE and
// tau : d2T/dE2 against central differences, equal and nearly equal eigenvalues
// included, and P = I / c in closed form at an isotropic state.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "mechanics/log_strain.hpp"

using namespace aster;
using namespace aster::mechanics;

namespace {

struct State {
  Eigen::Matrix2d E;
  double Ezz;
};

// The Voigt strain (E11, E22, E33, 2 E12) of a state and back.
Eigen::Vector4d voigt(const Eigen::Matrix2d& E, double Ezz) { return {E(0, 0), E(1, 1), Ezz, 2 * E(0, 1)}; }
State fromVoigt(const Eigen::Vector4d& v) {
  State s;
  s.E << v(0), v(3) / 2, v(3) / 2, v(1);
  s.Ezz = v(2);
  return s;
}
Eigen::Vector4d logVoigt(const Eigen::Vector4d& e) {
  const State s = fromVoigt(e);
  const LogarithmicStrain log(s.E, s.Ezz);
  return voigt(log.strain(), log.strainZZ());
}

Eigen::Matrix2d rotation(double theta) {
  Eigen::Matrix2d R;
  R << std::cos(theta), -std::sin(theta), std::sin(theta), std::cos(theta);
  return R;
}

// E = (U^2 - I)/2 of the stretch U = R diag(l1, l2) R^T, with the zz stretch l3.
State stretch(double l1, double l2, double l3, double theta) {
  const Eigen::Matrix2d R = rotation(theta);
  const Eigen::Matrix2d U = R * Eigen::Vector2d(l1, l2).asDiagonal() * R.transpose();
  return {0.5 * (U * U - Eigen::Matrix2d::Identity()), 0.5 * (l3 * l3 - 1)};
}

// The states the derivatives are checked at: distinct eigenvalues, in-plane equal
// ones, all three equal, nearly equal ones (1e-9 and 1e-5 apart, and about 1e-3
// relative on either side of where the second divided difference changes formula),
// the zz one equal to an in-plane one, and a large stretch.
std::vector<State> states() {
  return {stretch(1.3, 0.8, 1.1, 0.4),   stretch(1.2, 1.2, 0.9, 0.0),      stretch(1.2, 1.2, 1.2, 0.3),
          stretch(1.1, 1.1 + 1e-9, 1.0, 0.7), stretch(0.9, 0.9 + 1e-5, 0.9 - 1e-5, -0.2),
          stretch(1.0, 1.0 + 2.2e-4, 1.0 - 2.2e-4, 0.6), stretch(1.0, 1.0 + 2.8e-4, 1.0 - 2.8e-4, 0.6),
          stretch(1.25, 0.7, 1.25, 1.1), stretch(3.0, 0.4, 1.0, 0.25), stretch(1.0, 1.0, 1.0, 0.0)};
}

TEST(LogStrain, DiagonalStretch) {
  Eigen::Matrix2d E;
  E << 0.3, 0, 0, -0.2;
  const LogarithmicStrain log(E, 0.05);
  EXPECT_NEAR(log.strain()(0, 0), 0.5 * std::log(1.6), 1e-15);
  EXPECT_NEAR(log.strain()(1, 1), 0.5 * std::log(0.6), 1e-15);
  EXPECT_NEAR(log.strain()(0, 1), 0.0, 1e-15);
  EXPECT_NEAR(log.strain()(1, 0), 0.0, 1e-15);
  EXPECT_NEAR(log.strainZZ(), 0.5 * std::log(1.1), 1e-15);
}

TEST(LogStrain, RotatedStretch) {
  for (double theta : {0.3, -1.2, 2.0}) {
    const double l1 = 1.7, l2 = 0.6, l3 = 1.15;
    const State s = stretch(l1, l2, l3, theta);
    const LogarithmicStrain log(s.E, s.Ezz);
    const Eigen::Matrix2d R = rotation(theta);
    const Eigen::Matrix2d expected = R * Eigen::Vector2d(std::log(l1), std::log(l2)).asDiagonal() * R.transpose();
    EXPECT_LT((log.strain() - expected).norm(), 1e-14) << theta;
    EXPECT_NEAR(log.strainZZ(), std::log(l3), 1e-15);
  }
}

TEST(LogStrain, SmallStrainIsTheLinearizedStrain) {
  // T = E - E^2 + O(E^3): at |E| = 1e-9 the relative difference is about 1e-9, not rounding.
  Eigen::Matrix2d E;
  E << 1e-9, -3e-10, -3e-10, 2e-9;
  const LogarithmicStrain log(E, -1e-9);
  EXPECT_LT((log.strain() - (E - E * E)).norm(), 1e-23);
  EXPECT_NEAR(log.strainZZ(), -1e-9 - 1e-18, 1e-25);
}

TEST(LogStrain, IsotropicStateHasTheClosedFormProjector) {
  // E = a I: dT = dC / (2 c) = dE / c, so P = I / c, c = 1 + 2 a.
  const double a = 0.15, c = 1 + 2 * a;
  const LogarithmicStrain log(a * Eigen::Matrix2d::Identity(), a);
  EXPECT_LT((log.projector() - Eigen::Matrix4d::Identity() / c).norm(), 1e-15);
  // tau : d2T/dE2 = g''(c)/2 tau : (H K + K H) with H = 2 dE_b, K = 2 dE_c, g'' = -1/(2 c^2):
  // for tau = I (Voigt 1, 1, 1, 0), (b, c) = (xx, xx): -1/(4 c^2) 2 (2 * 2) = -2 / c^2.
  const Eigen::Matrix4d M = log.stressCurvature(Eigen::Vector4d(1, 1, 1, 0));
  EXPECT_NEAR(M(0, 0), -2 / (c * c), 1e-14);
  EXPECT_NEAR(M(0, 1), 0.0, 1e-14);
  // (xy, xy): H = K = off-diagonal ones, H K + K H = 2 diag(1, 1, 0): -1/(4 c^2) * 2 * 2.
  EXPECT_NEAR(M(3, 3), -1 / (c * c), 1e-14);
}

TEST(LogStrain, ProjectorMatchesDifferences) {
  const double h = 1e-6;
  for (const State& s : states()) {
    const LogarithmicStrain log(s.E, s.Ezz);
    const Eigen::Vector4d e = voigt(s.E, s.Ezz);
    Eigen::Matrix4d P;
    for (int b = 0; b < 4; ++b) {
      const Eigen::Vector4d d = Eigen::Vector4d::Unit(b) * h;
      P.col(b) = (logVoigt(e + d) - logVoigt(e - d)) / (2 * h);
    }
    EXPECT_LT((log.projector() - P).norm(), 1e-8 * P.norm()) << "E = " << e.transpose();
  }
}

TEST(LogStrain, StressCurvatureMatchesDifferences) {
  // tau : d2T/dE_b dE_c is the derivative of S_b = (P^T tau)_b for a fixed tau.
  const double h = 1e-6;
  const Eigen::Vector4d tau(2.0, -1.3, 0.7, 0.9);
  for (const State& s : states()) {
    const LogarithmicStrain log(s.E, s.Ezz);
    const Eigen::Vector4d e = voigt(s.E, s.Ezz);
    Eigen::Matrix4d M;
    for (int c = 0; c < 4; ++c) {
      const Eigen::Vector4d d = Eigen::Vector4d::Unit(c) * h;
      const State p = fromVoigt(e + d), m = fromVoigt(e - d);
      M.col(c) = (LogarithmicStrain(p.E, p.Ezz).projector().transpose() * tau -
                  LogarithmicStrain(m.E, m.Ezz).projector().transpose() * tau) /
                 (2 * h);
    }
    const Eigen::Matrix4d exact = log.stressCurvature(tau);
    EXPECT_LT((exact - M).norm(), 1e-8 * M.norm()) << "E = " << e.transpose();
    EXPECT_LT((exact - exact.transpose()).norm(), 1e-15 * exact.norm());
  }
}

TEST(LogStrain, RefusesASingularState) {
  Eigen::Matrix2d E;
  E << -0.5, 0, 0, 0.1;  // C11 = 0
  EXPECT_THROW(LogarithmicStrain(E, 0.0), Error);
  EXPECT_THROW(LogarithmicStrain(Eigen::Matrix2d::Zero(), -0.6), Error);
  E << 0.1, 0, 0, std::nan("");  // a diverged Newton iterate: the step is cut, no NaN spreads
  EXPECT_THROW(LogarithmicStrain(E, 0.0), Error);
}

}  // namespace
