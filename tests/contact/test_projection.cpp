// Closest-point projection on the SSNP150 master parabola Y = -0.05 (X-0.5)^2
// (one SEG3, or two SEG3 halves), against an independent reference computed
// in X (not xi): dense sampling of the distance, then bisection on its
// derivative. Ends, clamping, outside points, flat SEG2 hand cases.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "contact/projection.hpp"
#include "core/error.hpp"

using namespace aster::contact;
using Eigen::Vector2d;

namespace {

double parabola(double X) { return -0.05 * (X - 0.5) * (X - 0.5); }

// SSNP150's MAITRE: from (1.5,-0.05) to (-0.5,-0.05), middle (0.5,0):
// x(xi) = 0.5 - xi, y(xi) = -0.05 xi^2; normal points up (+Y).
Segment ssnp150Master() { return Segment::seg3({1.5, -0.05}, {-0.5, -0.05}, {0.5, 0.0}); }

struct Reference {
  double X = 0, gap = 0;
};

// Minimises d2(X) = (xs-X)^2 + (ys-parabola(X))^2 over [X0, X1].
Reference referenceProjection(const Vector2d& p, double X0, double X1) {
  auto d2 = [&](double X) { return std::pow(p(0) - X, 2) + std::pow(p(1) - parabola(X), 2); };
  auto dd2 = [&](double X) { return -2 * (p(0) - X) + 2 * (p(1) - parabola(X)) * 0.1 * (X - 0.5); };
  const int n = 20000;
  int best = 0;
  for (int k = 1; k <= n; ++k)
    if (d2(X0 + (X1 - X0) * k / n) < d2(X0 + (X1 - X0) * best / n)) best = k;
  double a = X0 + (X1 - X0) * std::max(0, best - 1) / n, b = X0 + (X1 - X0) * std::min(n, best + 1) / n;
  double X = X0 + (X1 - X0) * best / n;
  if (best > 0 && best < n) {
    for (int it = 0; it < 200; ++it) {
      const double m = 0.5 * (a + b);
      if (dd2(m) < 0) a = m; else b = m;
    }
    X = 0.5 * (a + b);
  }
  Reference r;
  r.X = X;
  const double dist = std::sqrt(d2(X));
  r.gap = p(1) >= parabola(p(0)) ? dist : -dist;  // above the parabola: separated
  return r;
}

}  // namespace

TEST(Projection, ParabolaMatchesIndependentReference) {
  const Segment m = ssnp150Master();
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> ux(-0.3, 1.3), uy(-0.5, 0.5);
  for (int k = 0; k < 200; ++k) {
    const Vector2d p(ux(gen), uy(gen));
    const Projection pr = projectOnSegment(p, m);
    const Reference ref = referenceProjection(p, -0.5, 1.5);
    ASSERT_EQ(pr.status, ProjectionStatus::Inside);
    EXPECT_NEAR(pr.xi, 0.5 - ref.X, 1e-12);
    EXPECT_NEAR(pr.gap, ref.gap, 1e-12);
    EXPECT_NEAR(pr.master.point(0), ref.X, 1e-12);
    EXPECT_NEAR(pr.master.point(1), parabola(ref.X), 1e-12);
    // Normal: upward unit normal of the parabola, (0.1(X-0.5), 1)/|.|.
    const Vector2d n = Vector2d(0.1 * (ref.X - 0.5), 1).normalized();
    EXPECT_NEAR((pr.master.normal - n).norm(), 0, 1e-10);
    EXPECT_NEAR(std::abs(pr.gap), pr.distance, 1e-13);
  }
}

TEST(Projection, PointsOnTheParabolaHaveZeroGap) {
  const Segment m = ssnp150Master();
  for (double X = -0.5; X <= 1.5 + 1e-12; X += 0.125) {
    const Projection pr = projectOnSegment(Vector2d(X, parabola(X)), m);
    EXPECT_NE(pr.status, ProjectionStatus::Outside);
    EXPECT_NEAR(pr.xi, 0.5 - X, 1e-12);
    EXPECT_NEAR(pr.gap, 0, 1e-15);
  }
}

TEST(Projection, PastAnEndIsClampedThenOutside) {
  const Segment m = ssnp150Master();
  // Past node 1 (1.5,-0.05), xi = -1, where dx/dxi = (-1, 0.1):
  // r = (p - x1).(-1, 0.1) and the overshoot is -r / |(-1,0.1)|^2.
  const Vector2d p(1.6, 0.0);
  const Projection pr = projectOnSegment(p, m);
  EXPECT_EQ(pr.status, ProjectionStatus::Clamped);
  EXPECT_EQ(pr.xi, -1.0);
  EXPECT_NEAR(pr.beyond, 0.095 / 1.01, 1e-14);
  const Vector2d n = Vector2d(0.1, 1).normalized();
  EXPECT_NEAR(pr.gap, (p - Vector2d(1.5, -0.05)).dot(n), 1e-14);
  const Projection far = projectOnSegment(Vector2d(3.0, 0.0), m);
  EXPECT_EQ(far.status, ProjectionStatus::Outside);
  EXPECT_NEAR(far.beyond, 1.495 / 1.01, 1e-13);
  ProjectionOptions strict;
  strict.outsideTolerance = 0.05;
  EXPECT_EQ(projectOnSegment(p, m, strict).status, ProjectionStatus::Outside);
  // Past node 2 (-0.5,-0.05), xi = +1, dx/dxi = (-1,-0.1).
  const Projection left = projectOnSegment(Vector2d(-0.7, -0.05), m);
  EXPECT_EQ(left.status, ProjectionStatus::Clamped);
  EXPECT_EQ(left.xi, 1.0);
  EXPECT_NEAR(left.beyond, 0.2 / 1.01, 1e-14);
}

TEST(Projection, SeveralSegmentsPickTheClosestValidOne) {
  // The same parabola as two SEG3 halves (exact: X is linear in each xi).
  const std::vector<Segment> halves = {
      Segment::seg3({1.5, -0.05}, {0.5, 0.0}, {1.0, parabola(1.0)}),
      Segment::seg3({0.5, 0.0}, {-0.5, -0.05}, {0.0, parabola(0.0)})};
  const Segment whole = ssnp150Master();
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> ux(-0.3, 1.3), uy(-0.3, 0.3);
  for (int k = 0; k < 100; ++k) {
    const Vector2d p(ux(gen), uy(gen));
    const MasterProjection mp = projectOnMaster(p, halves);
    const Projection ref = projectOnSegment(p, whole);
    ASSERT_TRUE(mp.paired());
    EXPECT_EQ(mp.projection.status, ProjectionStatus::Inside);
    EXPECT_EQ(mp.segment, ref.master.point(0) > 0.5 ? 0 : 1);
    EXPECT_NEAR((mp.projection.master.point - ref.master.point).norm(), 0, 1e-12);
    EXPECT_NEAR(mp.projection.gap, ref.gap, 1e-12);
  }
  const MasterProjection none = projectOnMaster(Vector2d(5.0, 0.0), halves);
  EXPECT_FALSE(none.paired());
  EXPECT_EQ(none.projection.status, ProjectionStatus::Outside);
  EXPECT_THROW(projectOnMaster(Vector2d(0, 0), {}), aster::Error);
}

TEST(Projection, FlatSeg2HandCase) {
  // Walked from (2,0) to (-1,0): normal (0,1). Slave at (0.5,h): g = h, xi = 0.
  const Segment m = Segment::seg2({2, 0}, {-1, 0});
  for (double h : {0.3, 0.0, -0.02}) {
    const Projection pr = projectOnSegment(Vector2d(0.5, h), m);
    EXPECT_EQ(pr.status, ProjectionStatus::Inside);
    EXPECT_NEAR(pr.xi, 0.0, 1e-15);
    EXPECT_NEAR(pr.gap, h, 1e-15);
  }
  const Projection end = projectOnSegment(Vector2d(2.0, 1.0), m);
  EXPECT_EQ(end.status, ProjectionStatus::Inside);  // exactly above the end
  EXPECT_EQ(end.xi, -1.0);
  EXPECT_NEAR(end.gap, 1.0, 1e-15);
}

TEST(Projection, RejectsBadInput) {
  Segment bad = Segment::seg2({0, 0}, {1, 0});
  bad.type = aster::fem::CellType::TRIA3;
  EXPECT_THROW(projectOnSegment(Vector2d(0, 0), bad), aster::Error);
  ProjectionOptions o;
  o.outsideTolerance = -1;
  EXPECT_THROW(projectOnSegment(Vector2d(0, 0), Segment::seg2({0, 0}, {1, 0}), o), aster::Error);
}

TEST(Projection, PairingDistanceLimit) {
  // DIST_APPA: the closest valid projection is kept only within maxDistance.
  const std::vector<Segment> m = {Segment::seg2({2, 0}, {-1, 0})};
  ProjectionOptions o;
  for (double limit : {-1.0, 0.5, 0.3001}) {
    o.maxDistance = limit;
    const MasterProjection p = projectOnMaster(Vector2d(0.5, 0.3), m, o);
    ASSERT_TRUE(p.paired()) << limit;
    EXPECT_NEAR(p.projection.gap, 0.3, 1e-15);
  }
  o.maxDistance = 0.2999;
  EXPECT_FALSE(projectOnMaster(Vector2d(0.5, 0.3), m, o).paired());
  EXPECT_FALSE(projectOnMaster(Vector2d(0.5, -0.3), m, o).paired());  // penetration counts as distance too
  EXPECT_TRUE(projectOnMaster(Vector2d(0.5, -0.2), m, o).paired());
}
