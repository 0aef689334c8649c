// Node-to-segment gap: hand values, and gradient/Hessian against central
// finite differences (each perturbed state re-projects) on random states with
// curved SEG3 masters, SEG2 masters and clamped projections.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "contact/gap.hpp"
#include "core/error.hpp"

using namespace aster::contact;
using Eigen::Vector2d;

namespace {

struct State {
  Vector2d xs;
  Segment master;
};

Eigen::VectorXd pack(const State& s) {
  const int m = s.master.nodes();
  Eigen::VectorXd q(2 + 2 * m);
  q.head<2>() = s.xs;
  for (int a = 0; a < m; ++a) q.segment<2>(2 + 2 * a) = s.master.x.row(a).transpose();
  return q;
}

State unpack(const Eigen::VectorXd& q, aster::fem::CellType type) {
  State s;
  s.xs = q.head<2>();
  s.master.type = type;
  const int m = s.master.nodes();
  for (int a = 0; a < m; ++a) s.master.x.row(a) = q.segment<2>(2 + 2 * a).transpose();
  return s;
}

NodeGap gapAt(const Eigen::VectorXd& q, aster::fem::CellType type) {
  const State s = unpack(q, type);
  return nodeToSegmentGap(s.xs, s.master);
}

// Checks gradient and Hessian by central differences, relative 1e-6.
void checkDerivatives(const State& s, ProjectionStatus expected) {
  const Eigen::VectorXd q = pack(s);
  const NodeGap g0 = gapAt(q, s.master.type);
  ASSERT_EQ(g0.projection.status, expected);
  const int n = static_cast<int>(q.size());
  ASSERT_EQ(g0.gradient.size(), n);
  const double h = 1e-6;
  Eigen::VectorXd fdGrad(n);
  Eigen::MatrixXd fdHess(n, n);
  for (int j = 0; j < n; ++j) {
    Eigen::VectorXd qp = q, qm = q;
    qp(j) += h;
    qm(j) -= h;
    const NodeGap gp = gapAt(qp, s.master.type), gm = gapAt(qm, s.master.type);
    ASSERT_EQ(gp.projection.status, expected);
    ASSERT_EQ(gm.projection.status, expected);
    fdGrad(j) = (gp.gap - gm.gap) / (2 * h);
    fdHess.col(j) = (Eigen::VectorXd(gp.gradient) - Eigen::VectorXd(gm.gradient)) / (2 * h);
  }
  const Eigen::VectorXd grad = g0.gradient;
  const Eigen::MatrixXd hess = g0.hessian;
  EXPECT_LE((grad - fdGrad).norm(), 1e-6 * std::max(1.0, grad.norm())) << "gradient\n" << grad.transpose() << "\nfd\n" << fdGrad.transpose();
  EXPECT_LE((hess - fdHess).norm(), 1e-6 * std::max(1.0, hess.norm())) << "hessian\n" << hess << "\nfd\n" << fdHess;
  EXPECT_LE((hess - hess.transpose()).norm(), 1e-12 * std::max(1.0, hess.norm()));
}

}  // namespace

TEST(Gap, FlatSeg2HandCase) {
  // Master walked from (2,0) to (-1,0): n = (0,1); slave at (0.5,h) projects at xi = 0.
  const Segment m = Segment::seg2({2, 0}, {-1, 0});
  const double h = 0.25;
  const NodeGap g = nodeToSegmentGap(Vector2d(0.5, h), m);
  EXPECT_NEAR(g.gap, h, 1e-15);
  // dg = (dxs - N1 dy1 - N2 dy2).n with N1 = N2 = 1/2.
  Eigen::VectorXd expected(6);
  expected << 0, 1, 0, -0.5, 0, -0.5;
  EXPECT_NEAR((Eigen::VectorXd(g.gradient) - expected).norm(), 0, 1e-15);
  // Second variation by hand: lifting y2 by e (y2 = (-1,e)), the master line has
  // n = (e,3)/sqrt(9+e^2) and g(e) = (3h - 1.5e)/sqrt(9+e^2), so g''(0) = -h/9.
  EXPECT_NEAR(g.hessian(5, 5), -h / 9, 1e-14);
  checkDerivatives(State{Vector2d(0.5, h), m}, ProjectionStatus::Inside);
}

TEST(Gap, CurvedSeg3RandomStatesMatchFiniteDifferences) {
  std::mt19937 gen(2024);
  std::uniform_real_distribution<double> u(-1, 1);
  int checked = 0;
  for (int k = 0; k < 40; ++k) {
    // A perturbed SSNP150-like curved master, strongly curved in some draws.
    Segment m = Segment::seg3({1.5 + 0.1 * u(gen), -0.05 + 0.1 * u(gen)}, {-0.5 + 0.1 * u(gen), -0.05 + 0.1 * u(gen)},
                              {0.5 + 0.1 * u(gen), 0.2 * u(gen)});
    const Vector2d xs(0.5 + 0.7 * u(gen), 0.3 * u(gen));
    const Projection p = projectOnSegment(xs, m);
    if (p.status != ProjectionStatus::Inside || std::abs(p.xi) > 0.9) continue;
    SCOPED_TRACE(k);
    checkDerivatives(State{xs, m}, ProjectionStatus::Inside);
    ++checked;
  }
  EXPECT_GE(checked, 20);
}

TEST(Gap, Seg2RandomStatesMatchFiniteDifferences) {
  std::mt19937 gen(99);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 20; ++k) {
    Segment m = Segment::seg2({1 + 0.2 * u(gen), 0.2 * u(gen)}, {-1 + 0.2 * u(gen), 0.2 * u(gen)});
    const Vector2d xs(0.6 * u(gen), 0.5 * u(gen));
    SCOPED_TRACE(k);
    checkDerivatives(State{xs, m}, ProjectionStatus::Inside);
  }
}

TEST(Gap, ClampedProjectionHoldsXiAtTheEnd) {
  const Segment m = Segment::seg3({1.5, -0.05}, {-0.5, -0.02}, {0.5, 0.03});
  const Vector2d xs(1.6, 0.05);
  const NodeGap g = nodeToSegmentGap(xs, m);
  ASSERT_EQ(g.projection.status, ProjectionStatus::Clamped);
  const auto f = segmentFrame(m, -1.0);
  EXPECT_NEAR(g.gap, (xs - f.point).dot(f.normal), 1e-15);
  checkDerivatives(State{xs, m}, ProjectionStatus::Clamped);
}

TEST(Gap, OutsideProjectionThrows) {
  const Segment m = Segment::seg2({1, 0}, {-1, 0});
  EXPECT_THROW(nodeToSegmentGap(Vector2d(5, 0.1), m), aster::Error);
}

TEST(Gap, RoundOffGapsCountAsClosed) {
  // A master on y = 0.3 and slave points at 3 x 0.1 = 0.30000000000000004, one
  // unit in the last place above it: a gap of 5.6E-17, closed. A gap of 1E-9
  // is open, whatever the coordinates' size; penetration is closed.
  for (const Segment& m : {Segment::seg2({1, 0.3}, {0, 0.3}), Segment::seg3({1, 0.3}, {0, 0.3}, {0.5, 0.3})}) {
    for (double x : {0.0, 0.25, 1.0 / 3, 0.5}) {
      const Vector2d xs(x, 3 * 0.1);
      const NodeGap g = nodeToSegmentGap(xs, m);
      ASSERT_GT(g.gap, 0);
      EXPECT_TRUE(gapIsClosed(g.gap, xs, m)) << x;
      EXPECT_TRUE(gapIsClosed(-1e-3, xs, m));
      const Vector2d open(x, 0.3 + 1e-9);
      EXPECT_FALSE(gapIsClosed(nodeToSegmentGap(open, m).gap, open, m)) << x;
    }
  }
  // The round-off follows the coordinates: the same geometry 1E4 farther away.
  const Segment far = Segment::seg2({1e4 + 1, 0.3}, {1e4, 0.3});
  EXPECT_DOUBLE_EQ(gapRoundOff(Vector2d(1e4 + 0.5, 0.3), far), 1e-12 * (1e4 + 1));
  EXPECT_TRUE(gapIsClosed(1e-9, Vector2d(1e4 + 0.5, 0.3), far));
  EXPECT_FALSE(gapIsClosed(1e-7, Vector2d(1e4 + 0.5, 0.3), far));
}
