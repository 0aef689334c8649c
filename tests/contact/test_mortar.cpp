// Mortar weighted gaps: hand integrals on straight segments (full and partial
// overlaps, a tilted master, a stretched slave), zero on a slave lying on a
// curved master, and exact gradients and Hessians against central finite
// differences on random curved pairs whose overlap ends at master nodes.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "contact/mortar.hpp"

using namespace aster::contact;
using aster::fem::CellType;
using Eigen::Vector2d;

namespace {

MortarSlave flatSlave(double x0, double x1) {
  MortarSlave s;
  s.type = CellType::SEG2;
  s.reference.row(0) << x0, 0;
  s.reference.row(1) << x1, 0;
  s.current = s.reference;
  return s;
}

}  // namespace

// Slave (0,0)-(1,0), outward normal (0,-1); master below at y = -d, walked
// from right to left (normal (0,1), facing the slave).
TEST(Mortar, ParallelSegmentsWeightTheGapByTheSharesOfTheOverlap) {
  const double d = 0.03;
  const auto slave = flatSlave(0, 1);
  const auto full = mortarPair(slave, Segment::seg2(Vector2d(1.2, -d), Vector2d(-0.3, -d)));
  ASSERT_TRUE(full.paired);
  EXPECT_DOUBLE_EQ(full.lo, -1);
  EXPECT_DOUBLE_EQ(full.hi, 1);
  EXPECT_NEAR(full.weightedGap[0].v, 0.5 * d, 1e-16);
  EXPECT_NEAR(full.weightedGap[1].v, 0.5 * d, 1e-16);
  // Master over x in [-0.3, 0.6]: xi in [-1, 0.2]; int_-1^0.2 (1 -+ xi)/2 dxi = 0.84, 0.36, times |dX/dxi| = 1/2.
  const auto part = mortarPair(slave, Segment::seg2(Vector2d(0.6, -d), Vector2d(-0.3, -d)));
  ASSERT_TRUE(part.paired);
  EXPECT_NEAR(part.hi, 0.2, 1e-15);
  EXPECT_NEAR(part.weightedGap[0].v, 0.42 * d, 1e-16);
  EXPECT_NEAR(part.weightedGap[1].v, 0.18 * d, 1e-16);
  EXPECT_NEAR(part.pairedShare[0], 0.42, 1e-15);
  // Penetration: the same with a negative gap.
  const auto pen = mortarPair(slave, Segment::seg2(Vector2d(1.2, d), Vector2d(-0.3, d)));
  EXPECT_NEAR(pen.weightedGap[0].v, -0.5 * d, 1e-16);
  // A master walked the other way faces away: no pair.
  EXPECT_FALSE(mortarPair(slave, Segment::seg2(Vector2d(-0.3, -d), Vector2d(1.2, -d))).paired);
  // Beyond DIST_APPA: no pair.
  MortarOptions o;
  o.maxDistance = 0.01;
  EXPECT_FALSE(mortarPair(slave, Segment::seg2(Vector2d(1.2, -d), Vector2d(-0.3, -d)), o).paired);
}

TEST(Mortar, TiltedMasterGivesTheIntegralOfTheLinearGap) {
  // Master y = -0.1 - 0.2 x: along the vertical normals g(x) = 0.1 + 0.2 x;
  // G_1 = int_0^1 (1 - x) g = 1/12, G_2 = int_0^1 x g = 7/60.
  const auto r = mortarPair(flatSlave(0, 1), Segment::seg2(Vector2d(1.5, -0.4), Vector2d(-0.5, 0.0)));
  ASSERT_TRUE(r.paired);
  EXPECT_NEAR(r.weightedGap[0].v, 1.0 / 12, 1e-15);
  EXPECT_NEAR(r.weightedGap[1].v, 7.0 / 60, 1e-15);
}

TEST(Mortar, IntegratesOnTheReferenceSlave) {
  // Reference (0,0)-(2,0), current (0,0)-(1,0): each node's share is 1 (reference length 2).
  auto slave = flatSlave(0, 2);
  slave.current.row(1) << 1, 0;
  const double d = 0.01;
  const auto r = mortarPair(slave, Segment::seg2(Vector2d(1.2, -d), Vector2d(-0.3, -d)));
  EXPECT_NEAR(r.weightedGap[0].v, d, 1e-16);
  EXPECT_NEAR(r.weightedGap[1].v, d, 1e-16);
  const auto shares = slaveShares(slave);
  EXPECT_NEAR(shares[0], 1, 1e-15);
  EXPECT_NEAR(shares[1], 1, 1e-15);
}

TEST(Mortar, SlaveOnTheParabolaHasNoGap) {
  // SSNP150's master: the SEG3 through (1.5,-0.05), (0.5,0), (-0.5,-0.05), i.e.
  // Y = -0.05 (X - 0.5)^2. A SEG3 slave on the same parabola (x from 0.2 to 0.4,
  // walked left to right, normal downwards) has G = 0 to round-off, since the
  // master is exactly that curve.
  const Segment master =
      Segment::seg3(Vector2d(1.5, -0.05), Vector2d(-0.5, -0.05), Vector2d(0.5, 0.0));
  auto parabola = [](double x) { return -0.05 * (x - 0.5) * (x - 0.5); };
  MortarSlave s;
  s.type = CellType::SEG3;
  s.reference.row(0) << 0.2, 0;
  s.reference.row(1) << 0.4, 0;
  s.reference.row(2) << 0.3, 0;
  s.current.row(0) << 0.2, parabola(0.2);
  s.current.row(1) << 0.4, parabola(0.4);
  s.current.row(2) << 0.3, parabola(0.3);
  const auto r = mortarPair(s, master);
  ASSERT_TRUE(r.paired);
  for (int j = 0; j < 3; ++j) EXPECT_NEAR(r.weightedGap[j].v, 0.0, 1e-17);
}

// Central differences of G_j and of its gradient over every coordinate.
namespace {

struct Pair {
  MortarSlave slave;
  Segment master;
};

Eigen::VectorXd pack(const Pair& p) {
  const int ns = p.slave.nodes(), nm = p.master.nodes();
  Eigen::VectorXd q(2 * (ns + nm));
  for (int a = 0; a < ns; ++a) q.segment<2>(2 * a) = p.slave.current.row(a).transpose();
  for (int b = 0; b < nm; ++b) q.segment<2>(2 * (ns + b)) = p.master.x.row(b).transpose();
  return q;
}
Pair unpack(Pair p, const Eigen::VectorXd& q) {
  const int ns = p.slave.nodes(), nm = p.master.nodes();
  for (int a = 0; a < ns; ++a) p.slave.current.row(a) = q.segment<2>(2 * a).transpose();
  for (int b = 0; b < nm; ++b) p.master.x.row(b) = q.segment<2>(2 * (ns + b)).transpose();
  return p;
}

// A slave over x in [0, 1] near y = 0 and a master below over [0.2, 0.75]
// (both overlap ends are master nodes), both perturbed at random.
Pair randomPair(CellType ts, CellType tm, std::mt19937& gen) {
  std::uniform_real_distribution<double> u(-0.02, 0.02);
  Pair p;
  p.slave.type = ts;
  p.slave.reference.row(0) << 0, 0;
  p.slave.reference.row(1) << 1, 0;
  p.slave.reference.row(2) << 0.5, 0;
  p.slave.current = p.slave.reference;
  for (int a = 0; a < p.slave.nodes(); ++a) p.slave.current.row(a) += Eigen::RowVector2d(u(gen), u(gen));
  const Vector2d m1(0.75 + u(gen), -0.01 + u(gen)), m2(0.2 + u(gen), -0.01 + u(gen));
  p.master = tm == CellType::SEG3 ? Segment::seg3(m1, m2, 0.5 * (m1 + m2) + Vector2d(u(gen), u(gen)))
                                  : Segment::seg2(m1, m2);
  return p;
}

}  // namespace

TEST(Mortar, GradientAndHessianMatchFiniteDifferences) {
  std::mt19937 gen(7);
  const CellType types[2] = {CellType::SEG2, CellType::SEG3};
  for (CellType ts : types)
    for (CellType tm : types)
      for (int trial = 0; trial < 4; ++trial) {
        const Pair p = randomPair(ts, tm, gen);
        const auto r = mortarPair(p.slave, p.master);
        ASSERT_TRUE(r.paired);
        ASSERT_GT(r.lo, -1);  // both ends at master nodes
        ASSERT_LT(r.hi, 1);
        const Eigen::VectorXd q = pack(p);
        const double h = 1e-6;
        for (int i = 0; i < q.size(); ++i) {
          Eigen::VectorXd qp = q, qm = q;
          qp(i) += h;
          qm(i) -= h;
          const Pair pp = unpack(p, qp), pm = unpack(p, qm);
          const auto rp = mortarPair(pp.slave, pp.master), rm = mortarPair(pm.slave, pm.master);
          for (int j = 0; j < p.slave.nodes(); ++j) {
            // Central differences: error h^2 times third derivatives of order 1.
            EXPECT_NEAR(r.weightedGap[j].g(i), (rp.weightedGap[j].v - rm.weightedGap[j].v) / (2 * h), 1e-8)
                << "slave " << aster::fem::cellName(ts) << " master " << aster::fem::cellName(tm) << " dof " << i;
            for (int k = 0; k < q.size(); ++k)
              EXPECT_NEAR(r.weightedGap[j].h(k, i),
                          (rp.weightedGap[j].g(k) - rm.weightedGap[j].g(k)) / (2 * h), 1e-7)
                  << "slave " << aster::fem::cellName(ts) << " master " << aster::fem::cellName(tm) << " dofs " << k
                  << ", " << i;
          }
        }
      }
}
