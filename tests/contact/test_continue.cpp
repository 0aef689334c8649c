// CONTINUE contact terms of one slave cell: the tangent against central finite
// differences of the residual (all DOFs: slave, curved SEG3 masters, LAGS_C)
// on random states mixing contact and separated points; hand cases (flat
// master, separated cell, slave lying on a curved master).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/LU>

#include "contact/continue_formulation.hpp"
#include "core/error.hpp"

#include "continue_fixtures.hpp"

using namespace aster::contact;
using namespace aster::contact::testing;
using aster::fem::CellType;
using Eigen::Vector2d;

namespace {

// Cell DOFs <-> (slave current coordinates, master coordinates, the nm LAGS_C).
Eigen::VectorXd pack(const SlaveCell& s, const std::vector<Segment>& masters, int nm) {
  std::vector<double> v;
  const int ns = s.type == CellType::SEG3 ? 3 : 2;
  for (int a = 0; a < ns; ++a) v.push_back(s.current(a, 0)), v.push_back(s.current(a, 1));
  for (const auto& m : masters)
    for (int a = 0; a < m.nodes(); ++a) v.push_back(m.x(a, 0)), v.push_back(m.x(a, 1));
  for (int a = 0; a < nm; ++a) v.push_back(s.lagsC(a));
  return Eigen::Map<Eigen::VectorXd>(v.data(), v.size());
}

void unpack(const Eigen::VectorXd& q, SlaveCell& s, std::vector<Segment>& masters, int nm) {
  int k = 0;
  const int ns = s.type == CellType::SEG3 ? 3 : 2;
  for (int a = 0; a < ns; ++a) s.current(a, 0) = q(k++), s.current(a, 1) = q(k++);
  for (auto& m : masters)
    for (int a = 0; a < m.nodes(); ++a) m.x(a, 0) = q(k++), m.x(a, 1) = q(k++);
  for (int a = 0; a < nm; ++a) s.lagsC(a) = q(k++);
}

// Returns false (state not usable) when a status flips under perturbation.
bool checkTangent(SlaveCell s, std::vector<Segment> masters, const ContinueOptions& o) {
  ContinueCellTerms t0, tp, tm;
  continueCellTerms(s, masters, o, t0);
  const int nm = multiplierCount(s, o);
  const Eigen::VectorXd q = pack(s, masters, nm);
  EXPECT_EQ(q.size(), t0.size());
  const double h = 1e-7;
  Eigen::MatrixXd fd(q.size(), q.size());
  for (int j = 0; j < q.size(); ++j) {
    Eigen::VectorXd qp = q, qm = q;
    qp(j) += h;
    qm(j) -= h;
    SlaveCell sp = s, sm = s;
    std::vector<Segment> mp = masters, mm = masters;
    unpack(qp, sp, mp, nm);
    unpack(qm, sm, mm, nm);
    continueCellTerms(sp, mp, o, tp);
    continueCellTerms(sm, mm, o, tm);
    if (statuses(tp) != statuses(t0) || statuses(tm) != statuses(t0)) return false;
    fd.col(j) = (tp.residual - tm.residual) / (2 * h);
  }
  const double scale = std::max(1.0, t0.tangent.norm());
  EXPECT_LE((t0.tangent - fd).norm(), 1e-6 * scale) << "tangent\n" << t0.tangent << "\nfd\n" << fd;
  EXPECT_LE((t0.tangent - t0.tangent.transpose()).norm(), 1e-12 * scale);
  return true;
}

}  // namespace

TEST(Continue, TangentMatchesFiniteDifferencesOnCurvedMasters) {
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> u(-1, 1);
  const std::vector<Segment> oneMaster = {Segment::seg3({1.5, -0.05}, {-0.5, -0.05}, {0.5, 0.0})};
  const std::vector<Segment> twoMasters = {Segment::seg3({1.5, -0.05}, {0.5, 0.0}, {1.0, parabola(1.0)}),
                                           Segment::seg3({0.5, 0.0}, {-0.5, -0.05}, {0.0, parabola(0.0)})};
  int checked = 0, mixed = 0, split = 0;
  for (int k = 0; k < 60; ++k) {
    const CellType type = k % 2 ? CellType::SEG3 : CellType::SEG2;
    SlaveCell s = slaveAlong(type, 0.2 + 0.1 * u(gen), 0.8 + 0.1 * u(gen), gen, 0.01);
    s.lagsC << 0.5 * u(gen) - 0.2, 0.5 * u(gen) - 0.2, 0;
    std::vector<Segment> masters = k % 3 ? oneMaster : twoMasters;
    for (auto& m : masters)
      for (int a = 0; a < m.nodes(); ++a) m.x.row(a) += 0.01 * Eigen::RowVector2d(u(gen), u(gen));
    ContinueOptions o;
    o.rho = k % 4 ? 100 : 3;
    o.gaussPoints = 2 + k % 3;
    if (k % 5 == 0) o.integration = ContactIntegration::Nodes;
    ContinueCellTerms t;
    continueCellTerms(s, masters, o, t);
    bool nearSwitch = false;
    int contact = 0;
    std::vector<int> segs;
    for (const auto& p : t.points) {
      nearSwitch = nearSwitch || std::abs(p.augmented) < 1e-4;
      contact += p.status == PointStatus::Contact;
      segs.push_back(p.masterSegment);
    }
    if (nearSwitch) continue;
    SCOPED_TRACE(k);
    if (!checkTangent(s, masters, o)) continue;
    ++checked;
    mixed += contact > 0 && contact < static_cast<int>(t.points.size());
    split += segs.front() != segs.back();
  }
  EXPECT_GE(checked, 40);
  EXPECT_GE(mixed, 5);  // states with contact and separated points in one cell
  EXPECT_GE(split, 3);  // cells whose points pair with two different master segments
}

TEST(Continue, FlatMasterHandCase) {
  // Master y = 0 walked from (2,0) to (-1,0) (normal +Y); slave SEG2 at y = h,
  // reference length 2 (a stretched current length 1 must not matter).
  const std::vector<Segment> masters = {Segment::seg2({2, 0}, {-1, 0})};
  SlaveCell s;
  s.type = CellType::SEG2;
  s.reference.row(0) << 0, -1;
  s.reference.row(1) << 2, -1;
  const double h = 0.02;
  s.current.row(0) << 0, h;
  s.current.row(1) << 1, h;
  ContinueOptions o;
  ContinueCellTerms t;
  // Separated with lambda = 0: nothing at all.
  continueCellTerms(s, masters, o, t);
  ASSERT_EQ(t.points.size(), 3u);
  for (const auto& p : t.points) {
    EXPECT_EQ(p.status, PointStatus::Separated);
    EXPECT_NEAR(p.gap, h, 1e-15);
  }
  EXPECT_EQ(t.residual.norm(), 0.0);
  // On the master (h = 0) with a uniform pressure p < 0: the LAGS_C rows
  // vanish; the slave nodes get p * L0/2 * n_m each (the master pushes the
  // slave by -p n_m: R = F_int - F_ext receives +p n_m), the master the opposite.
  s.current.col(1).setZero();
  const double p = -0.7;
  s.lagsC << p, p, 0;
  continueCellTerms(s, masters, o, t);
  for (const auto& pt : t.points) {
    EXPECT_EQ(pt.status, PointStatus::Contact);
    EXPECT_NEAR(pt.pressure, p, 1e-15);
  }
  EXPECT_NEAR(t.residual.segment<2>(t.lagrangeOffset).norm(), 0, 1e-15);
  EXPECT_NEAR(t.residual(0), 0, 1e-15);
  EXPECT_NEAR(t.residual(1), p * 1.0, 1e-14);
  EXPECT_NEAR(t.residual(3), p * 1.0, 1e-14);
  // Master: x = 0.5 - 1.5 xi, so N1 = (1+x)/3, N2 = (2-x)/3 at the slave points,
  // spread uniformly over x in [0,1] (x = X/2): the resultant -2p (along +Y)
  // splits as 2 * mean(N1) = 1 and 2 * mean(N2) = 1 times -p.
  const int m = t.masterOffsets[0];
  EXPECT_NEAR(t.residual(m + 1), -p, 1e-14);
  EXPECT_NEAR(t.residual(m + 3), -p, 1e-14);
  EXPECT_NEAR(t.residual(m), 0, 1e-15);
  // Penetrating point with lambda = 0 switches to contact (lambda + rho g < 0).
  s.lagsC.setZero();
  s.current.col(1).setConstant(-1e-3);
  continueCellTerms(s, masters, o, t);
  for (const auto& pt : t.points) EXPECT_EQ(pt.status, PointStatus::Contact);
  // Its LAGS_C rows are int g L dGamma_0 = g * L0/2 each.
  EXPECT_NEAR(t.residual(t.lagrangeOffset), -1e-3, 1e-15);
}

TEST(Continue, SlaveLyingOnTheCurvedMasterHasZeroGap) {
  // SSNP150 at the exact solution: BAS (Y = 0) moves by Uy = -0.05 (X-0.5)^2,
  // Ux = 0, onto the master parabola. A SEG3 slave with its middle node at the
  // middle X is then exactly a piece of the parabola.
  const std::vector<Segment> masters = {Segment::seg3({1.5, -0.05}, {-0.5, -0.05}, {0.5, 0.0})};
  for (CellType type : {CellType::SEG3, CellType::SEG2}) {
    for (double x0 : {0.0, 0.25, 0.8125}) {
      const double x1 = x0 + 0.1875;
      SlaveCell s;
      s.type = type;
      s.reference.row(0) << x0, 0;
      s.reference.row(1) << x1, 0;
      s.reference.row(2) << 0.5 * (x0 + x1), 0;
      for (int a = 0; a < 3; ++a) s.current.row(a) << s.reference(a, 0), parabola(s.reference(a, 0));
      s.lagsC << -0.3, -0.2, 0;
      for (ContactIntegration integ : {ContactIntegration::Gauss, ContactIntegration::Nodes}) {
        ContinueOptions o;
        o.integration = integ;
        ContinueCellTerms t;
        continueCellTerms(s, masters, o, t);
        for (const auto& p : t.points) {
          if (type == CellType::SEG3 || std::abs(p.xi) == 1.0) {  // a SEG2 is on it at its nodes only
            EXPECT_NEAR(p.gap, 0, 1e-15);
          }
          EXPECT_EQ(p.status, PointStatus::Contact);
        }
        // Zero gaps at every point: the LAGS_C rows vanish (Newton-Cotes on a
        // SEG2 uses its nodes).
        if (type == CellType::SEG3 || integ == ContactIntegration::Nodes) {
          EXPECT_NEAR(t.residual.segment<2>(t.lagrangeOffset).norm(), 0, 1e-15);
        }
      }
    }
  }
}

TEST(Continue, SlaveTouchingToRoundOffIsInContact) {
  // A slave one unit in the last place above a flat master (y = 3 x 0.1 on
  // y = 0.3), LAGS_C = 0: the start of two bodies meshed to touch. Every point
  // is in contact (else a body held by contact alone is free); 1E-9 above,
  // every point is separated.
  const std::vector<Segment> masters = {Segment::seg3({1.5, 0.3}, {-0.5, 0.3}, {0.5, 0.3})};
  for (CellType type : {CellType::SEG3, CellType::SEG2}) {
    for (double y : {3 * 0.1, 0.3 + 1e-9}) {
      SlaveCell s;
      s.type = type;
      s.reference.row(0) << 0.2, y;
      s.reference.row(1) << 0.6, y;
      s.reference.row(2) << 0.4, y;
      s.current = s.reference;
      for (double penalty : {0.0, 100.0}) {
        ContinueOptions o;
        o.penalty = penalty;
        ContinueCellTerms t;
        continueCellTerms(s, masters, o, t);
        for (const auto& p : t.points) {
          EXPECT_EQ(p.status, y < 0.3 + 1e-12 ? PointStatus::Contact : PointStatus::Separated) << y << " " << p.xi;
          if (y < 0.3 + 1e-12) {
            EXPECT_GT(p.gap, 0);
          }
        }
      }
    }
  }
}

TEST(Continue, UnpairedPointsAreSeparatedAndBadInputThrows) {
  const std::vector<Segment> masters = {Segment::seg2({1, 0}, {0, 0})};
  SlaveCell s;
  s.type = CellType::SEG2;
  s.reference.row(0) << 5, 0;
  s.reference.row(1) << 6, 0;
  s.current = s.reference;
  s.lagsC << -1, -1, 0;
  ContinueOptions o;
  ContinueCellTerms t;
  continueCellTerms(s, masters, o, t);
  for (const auto& p : t.points) EXPECT_EQ(p.status, PointStatus::Unpaired);
  // -(lambda/rho) int L dGamma_0 = (1/100) * 1/2 per node.
  EXPECT_NEAR(t.residual(t.lagrangeOffset), 0.005, 1e-15);
  o.rho = 0;
  EXPECT_THROW(continueCellTerms(s, masters, o, t), aster::Error);
  o.rho = 100;
  o.gaussPoints = 0;
  EXPECT_THROW(continueCellTerms(s, masters, o, t), aster::Error);
  o.gaussPoints = 3;
  EXPECT_THROW(continueCellTerms(s, {}, o, t), aster::Error);
}

namespace {

// A SEG3 slave whose nodes are tied by springs (stiffness k) to anchors below
// the fixed curved master: the springs push it into the master. Unknowns: the
// slave coordinates and LAGS_C (master DOFs held fixed). Generalized Newton
// with the exact tangent must converge quadratically once statuses settle.
void newtonOnASpringLoadedSlave(MultiplierInterpolation interpolation) {
  const std::vector<Segment> masters = {Segment::seg3({1.5, -0.05}, {-0.5, -0.05}, {0.5, 0.0})};
  SlaveCell s;
  s.type = CellType::SEG3;
  s.reference << 0.1, 0, 0.9, 0, 0.5, 0;
  Eigen::Matrix<double, 3, 2> anchor;
  anchor << 0.12, -0.08, 0.93, -0.06, 0.52, -0.05;
  s.current << 0.1, 0.02, 0.9, 0.02, 0.5, 0.03;  // start separated
  const double k = 2.0;
  ContinueOptions o;
  o.rho = 10;
  o.multiplierInterpolation = interpolation;
  const int nm = multiplierCount(s, o);
  const int nf = 6 + nm;
  ContinueCellTerms t;
  std::vector<double> norms;
  for (int it = 0; it < 30; ++it) {
    continueCellTerms(s, masters, o, t);
    // Free DOFs: slave 0..5 and LAGS_C; master columns dropped (fixed).
    Eigen::VectorXd R(nf);
    Eigen::MatrixXd K(nf, nf);
    const int lo = t.lagrangeOffset;
    ASSERT_EQ(t.size(), lo + nm);
    std::vector<int> idx = {0, 1, 2, 3, 4, 5};
    for (int v = 0; v < nm; ++v) idx.push_back(lo + v);
    for (int i = 0; i < nf; ++i) {
      R(i) = t.residual(idx[i]);
      for (int j = 0; j < nf; ++j) K(i, j) = t.tangent(idx[i], idx[j]);
    }
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 2; ++c) {
        R(2 * a + c) += k * (s.current(a, c) - anchor(a, c));
        K(2 * a + c, 2 * a + c) += k;
      }
    norms.push_back(R.norm());
    if (R.norm() < 1e-14) break;
    const Eigen::VectorXd d = K.fullPivLu().solve(-R);
    for (int a = 0; a < 3; ++a) s.current.row(a) += d.segment<2>(2 * a).transpose();
    s.lagsC.head(nm) += d.tail(nm);
  }
  ASSERT_LT(norms.back(), 1e-14);
  ASSERT_LE(norms.size(), 15u);
  // Quadratic rate on the last steps: r_{i+1} <= C r_i^2 with a moderate C.
  int quadratic = 0;
  for (std::size_t i = 1; i + 1 < norms.size(); ++i)
    if (norms[i] < 1e-2 && norms[i + 1] > 1e-15) {
      EXPECT_LE(norms[i + 1], 100 * norms[i] * norms[i]) << "step " << i;
      ++quadratic;
    }
  EXPECT_GE(quadratic, 1);
  if (interpolation == MultiplierInterpolation::Linear) {
    // At the solution: in contact, compressive pressure, zero weighted gaps.
    for (const auto& p : t.points) {
      EXPECT_EQ(p.status, PointStatus::Contact);
      EXPECT_LT(p.pressure, 0);
    }
    EXPECT_LT(s.lagsC.head(nm).maxCoeff(), 0);
    return;
  }
  // Quadratic: 3 LAGS_C against 3 Gauss points (an invertible 3x3 matrix of
  // L_v(xi_i)) decouple the constraint rows into one per point, so the middle
  // point may, and here does, lift off (the springs press the ends harder):
  // g = 0 at contact points, lambda = 0 < g at separated ones.
  int contact = 0, separated = 0;
  for (const auto& p : t.points) {
    if (p.status == PointStatus::Contact) {
      ++contact;
      EXPECT_NEAR(p.gap, 0, 1e-14);
      EXPECT_LT(p.pressure, 0);
    } else {
      ++separated;
      EXPECT_EQ(p.status, PointStatus::Separated);
      EXPECT_NEAR(p.pressure, 0, 1e-14);
      EXPECT_GT(p.gap, 0);
    }
  }
  EXPECT_EQ(contact, 2);
  EXPECT_EQ(separated, 1);
}

}  // namespace

TEST(Continue, NewtonConvergesQuadraticallyOnASpringLoadedSlave) {
  newtonOnASpringLoadedSlave(MultiplierInterpolation::Linear);
}

// ------------------------------------------------ quadratic LAGS_C (SEG3 slave)

TEST(ContinueQuadratic, MultiplierCountAndLayout) {
  SlaveCell s2, s3;
  s2.type = CellType::SEG2;
  s3.type = CellType::SEG3;
  ContinueOptions lin, quad;
  quad.multiplierInterpolation = MultiplierInterpolation::Quadratic;
  EXPECT_EQ(lin.multiplierInterpolation, MultiplierInterpolation::Linear);  // the default
  EXPECT_EQ(multiplierCount(s2, lin), 2);
  EXPECT_EQ(multiplierCount(s3, lin), 2);
  EXPECT_EQ(multiplierCount(s2, quad), 2);
  EXPECT_EQ(multiplierCount(s3, quad), 3);
  s3.reference << 0, 0, 1, 0, 0.5, 0;
  s3.current = s3.reference;
  const std::vector<Segment> masters = {Segment::seg2({1, 0}, {0, 0}), Segment::seg3({2, 0}, {1, 0}, {1.5, 0})};
  ContinueCellTerms t;
  continueCellTerms(s3, masters, quad, t);
  EXPECT_EQ(t.masterOffsets, (std::vector<int>{6, 10}));
  EXPECT_EQ(t.lagrangeOffset, 16);
  EXPECT_EQ(t.size(), 19);
  continueCellTerms(s3, masters, lin, t);
  EXPECT_EQ(t.lagrangeOffset, 16);
  EXPECT_EQ(t.size(), 18);
}

TEST(ContinueQuadratic, Seg2SlaveAndUnusedThirdEntryChangeNothing) {
  // A SEG2 slave in Quadratic mode is Linear, bit for bit; in Linear mode the
  // third LAGS_C entry of a SEG3 slave is ignored.
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-1, 1);
  const std::vector<Segment> masters = {Segment::seg3({1.5, -0.05}, {-0.5, -0.05}, {0.5, 0.0})};
  for (int k = 0; k < 20; ++k) {
    const CellType type = k % 2 ? CellType::SEG3 : CellType::SEG2;
    SlaveCell s = slaveAlong(type, 0.2, 0.8, gen, 0.01);
    s.lagsC << 0.5 * u(gen) - 0.2, 0.5 * u(gen) - 0.2, 0;
    ContinueOptions lin;
    lin.integration = k % 4 < 2 ? ContactIntegration::Gauss : ContactIntegration::Nodes;
    ContinueOptions quad = lin;
    quad.multiplierInterpolation = MultiplierInterpolation::Quadratic;
    ContinueCellTerms a, b;
    continueCellTerms(s, masters, lin, a);
    if (type == CellType::SEG2) {
      continueCellTerms(s, masters, quad, b);
    } else {
      s.lagsC(2) = 12.5;  // unused
      continueCellTerms(s, masters, lin, b);
    }
    EXPECT_TRUE(a.residual == b.residual);
    EXPECT_TRUE(a.tangent == b.tangent);
  }
}

TEST(ContinueQuadratic, TangentMatchesFiniteDifferencesOnCurvedMasters) {
  std::mt19937 gen(17);
  std::uniform_real_distribution<double> u(-1, 1);
  const std::vector<Segment> oneMaster = {Segment::seg3({1.5, -0.05}, {-0.5, -0.05}, {0.5, 0.0})};
  const std::vector<Segment> twoMasters = {Segment::seg3({1.5, -0.05}, {0.5, 0.0}, {1.0, parabola(1.0)}),
                                           Segment::seg3({0.5, 0.0}, {-0.5, -0.05}, {0.0, parabola(0.0)})};
  int checked = 0, mixed = 0, split = 0;
  for (int k = 0; k < 60; ++k) {
    SlaveCell s = slaveAlong(CellType::SEG3, 0.2 + 0.1 * u(gen), 0.8 + 0.1 * u(gen), gen, 0.01);
    s.lagsC << 0.5 * u(gen) - 0.2, 0.5 * u(gen) - 0.2, 0.5 * u(gen) - 0.2;
    std::vector<Segment> masters = k % 3 ? oneMaster : twoMasters;
    for (auto& m : masters)
      for (int a = 0; a < m.nodes(); ++a) m.x.row(a) += 0.01 * Eigen::RowVector2d(u(gen), u(gen));
    ContinueOptions o;
    o.multiplierInterpolation = MultiplierInterpolation::Quadratic;
    o.rho = k % 4 ? 100 : 3;
    o.gaussPoints = 3 + k % 3;
    if (k % 5 == 0) o.integration = ContactIntegration::Nodes;
    ContinueCellTerms t;
    continueCellTerms(s, masters, o, t);
    ASSERT_EQ(t.size() - t.lagrangeOffset, 3);
    bool nearSwitch = false;
    int contact = 0;
    std::vector<int> segs;
    for (const auto& p : t.points) {
      nearSwitch = nearSwitch || std::abs(p.augmented) < 1e-4;
      contact += p.status == PointStatus::Contact;
      segs.push_back(p.masterSegment);
    }
    if (nearSwitch) continue;
    SCOPED_TRACE(k);
    if (!checkTangent(s, masters, o)) continue;
    ++checked;
    mixed += contact > 0 && contact < static_cast<int>(t.points.size());
    split += segs.front() != segs.back();
  }
  EXPECT_GE(checked, 40);
  EXPECT_GE(mixed, 5);  // states with contact and separated points in one cell
  EXPECT_GE(split, 3);  // cells whose points pair with two different master segments
}

namespace {

// int_{-1}^{1} N_a N_b dxi for the SEG3 shape functions (nodes 1, 2, 3).
Eigen::Matrix3d seg3Mass() {
  Eigen::Matrix3d M;
  M << 4, -1, 2, -1, 4, 2, 2, 2, 16;
  return M / 15;
}

}  // namespace

TEST(ContinueQuadratic, QuadraticPressureOnAFlatMasterIsExact) {
  // Master y = 0 walked from (2,0) to (-1,0) (normal +Y); SEG3 slave lying on
  // it, reference length 2 (|dX/dxi| = 1), current x = (1+xi)/2. The pressure
  // p(xi) = a + b xi + c xi^2 < 0 is given exactly by its three nodal values.
  const std::vector<Segment> masters = {Segment::seg2({2, 0}, {-1, 0})};
  SlaveCell s;
  s.type = CellType::SEG3;
  s.reference << 0, -1, 2, -1, 1, -1;
  s.current << 0, 0, 1, 0, 0.5, 0;
  const double a = -0.8, b = 0.3, c = 0.2;
  auto p = [&](double xi) { return a + b * xi + c * xi * xi; };
  s.lagsC << p(-1), p(1), p(0);
  const Eigen::Vector3d F = seg3Mass() * s.lagsC;  // consistent nodal forces int p N_a
  for (int ng : {3, 4, 5}) {
    SCOPED_TRACE(ng);
    ContinueOptions o;
    o.multiplierInterpolation = MultiplierInterpolation::Quadratic;
    o.gaussPoints = ng;
    ContinueCellTerms t;
    continueCellTerms(s, masters, o, t);
    ASSERT_EQ(static_cast<int>(t.points.size()), ng);
    for (const auto& pt : t.points) {
      EXPECT_EQ(pt.status, PointStatus::Contact);
      EXPECT_EQ(pt.gap, 0.0);
      EXPECT_NEAR(pt.pressure, p(pt.xi), 1e-15);
    }
    // The constraint rows int g N_v dGamma_0 vanish, and the force rows are the
    // consistent nodal forces of p (degree 4: exact with >= 3 Gauss points).
    const int lo = t.lagrangeOffset;
    ASSERT_EQ(t.size(), lo + 3);
    EXPECT_EQ(t.residual.segment<3>(lo).norm(), 0.0);
    for (int n = 0; n < 3; ++n) {
      EXPECT_NEAR(t.residual(2 * n), 0, 1e-15);
      EXPECT_NEAR(t.residual(2 * n + 1), F(n), 1e-15);
    }
    // Master: the opposite resultant and moment (int p x dGamma_0, x = (1+xi)/2).
    const int m = t.masterOffsets[0];
    EXPECT_NEAR(t.residual(m) + t.residual(m + 2), 0, 1e-15);
    EXPECT_NEAR(t.residual(m + 1) + t.residual(m + 3), -F.sum(), 1e-14);
    const double moment = 0.5 * F.sum() + 0.5 * (seg3Mass() * Eigen::Vector3d(-1, 1, 0)).dot(s.lagsC);
    EXPECT_NEAR(2 * t.residual(m + 1) - t.residual(m + 3), -moment, 1e-14);
    EXPECT_NEAR(s.current.col(0).dot(t.residual.segment<6>(0)(Eigen::seqN(1, 3, 2))), moment, 1e-14);
  }
  // Uniform penetration g: the constraint rows are g int N_v = g (1/3, 1/3, 4/3).
  s.current.col(1).setConstant(-1e-3);
  for (ContactIntegration integ : {ContactIntegration::Gauss, ContactIntegration::Nodes}) {
    ContinueOptions o;
    o.multiplierInterpolation = MultiplierInterpolation::Quadratic;
    o.integration = integ;
    ContinueCellTerms t;
    continueCellTerms(s, masters, o, t);
    const Eigen::Vector3d expected = -1e-3 * Eigen::Vector3d(1.0 / 3, 1.0 / 3, 4.0 / 3);
    EXPECT_NEAR((t.residual.segment<3>(t.lagrangeOffset) - expected).norm(), 0, 1e-16);
  }
}

TEST(ContinueQuadratic, SeparatedMultiplierBlockAndGaussPointCount) {
  // Separated straight SEG3 slave (|dX/dxi| = 1.5): the LAGS_C rows are
  // -(1/rho) int lambda N_v dGamma_0, i.e. -(1.5/rho) M lagsC with the SEG3
  // mass M (degree 4: exact with 3 Gauss points and more), diagonal (lumped,
  // Simpson weights) when integrated at the nodes.
  const std::vector<Segment> masters = {Segment::seg2({4, 0}, {-1, 0})};
  SlaveCell s;
  s.type = CellType::SEG3;
  s.reference << 0, 0, 3, 0, 1.5, 0;
  s.current << 0, 0.5, 3, 0.5, 1.5, 0.5;
  s.lagsC << -0.4, 0.3, -0.7;
  ContinueOptions o;
  o.multiplierInterpolation = MultiplierInterpolation::Quadratic;
  o.rho = 4;
  const Eigen::Matrix3d exact = -1.5 / o.rho * seg3Mass();
  ContinueCellTerms t;
  for (int ng : {3, 4, 6}) {
    o.gaussPoints = ng;
    continueCellTerms(s, masters, o, t);
    for (const auto& pt : t.points) EXPECT_EQ(pt.status, PointStatus::Separated);
    const int lo = t.lagrangeOffset;
    EXPECT_NEAR((t.tangent.block<3, 3>(lo, lo) - exact).norm(), 0, 1e-15) << ng;
    EXPECT_NEAR((t.residual.segment<3>(lo) - exact * s.lagsC).norm(), 0, 1e-15) << ng;
    EXPECT_EQ(t.residual.head(lo).norm(), 0.0);
  }
  o.integration = ContactIntegration::Nodes;
  continueCellTerms(s, masters, o, t);
  const Eigen::Matrix3d lumped = -1.5 / o.rho * Eigen::Vector3d(1.0 / 3, 1.0 / 3, 4.0 / 3).asDiagonal().toDenseMatrix();
  EXPECT_NEAR((t.tangent.block<3, 3>(t.lagrangeOffset, t.lagrangeOffset) - lumped).norm(), 0, 1e-15);
  // Fewer than 3 Gauss points would make that block singular: rejected.
  o.integration = ContactIntegration::Gauss;
  for (int ng : {1, 2}) {
    o.gaussPoints = ng;
    EXPECT_THROW(continueCellTerms(s, masters, o, t), aster::Error);
  }
  // ... but not in Linear mode, nor for a SEG2 slave in Quadratic mode.
  o.multiplierInterpolation = MultiplierInterpolation::Linear;
  EXPECT_NO_THROW(continueCellTerms(s, masters, o, t));
  o.multiplierInterpolation = MultiplierInterpolation::Quadratic;
  s.type = CellType::SEG2;
  EXPECT_NO_THROW(continueCellTerms(s, masters, o, t));
}

TEST(ContinueQuadratic, NewtonConvergesQuadraticallyOnASpringLoadedSlave) {
  newtonOnASpringLoadedSlave(MultiplierInterpolation::Quadratic);
}

// ------------------------------------------------ penalisation, forced statuses

TEST(ContinuePenalised, TangentMatchesFiniteDifferencesOnCurvedMasters) {
  std::mt19937 gen(17);
  std::uniform_real_distribution<double> u(-1, 1);
  const std::vector<Segment> twoMasters = {Segment::seg3({1.5, -0.05}, {0.5, 0.0}, {1.0, parabola(1.0)}),
                                           Segment::seg3({0.5, 0.0}, {-0.5, -0.05}, {0.0, parabola(0.0)})};
  int checked = 0, mixed = 0;
  for (int k = 0; k < 40; ++k) {
    const CellType type = k % 2 ? CellType::SEG3 : CellType::SEG2;
    SlaveCell s = slaveAlong(type, 0.2 + 0.1 * u(gen), 0.8 + 0.1 * u(gen), gen, 0.01);
    s.lagsC << 0.5 * u(gen) - 0.2, 0.5 * u(gen) - 0.2, 0.5 * u(gen) - 0.2;
    std::vector<Segment> masters = twoMasters;
    for (auto& m : masters)
      for (int a = 0; a < m.nodes(); ++a) m.x.row(a) += 0.01 * Eigen::RowVector2d(u(gen), u(gen));
    ContinueOptions o;
    o.penalty = k % 3 ? 50 : 2;
    o.gaussPoints = 3;
    if (k % 4 == 0) o.multiplierInterpolation = MultiplierInterpolation::Quadratic;
    if (k % 5 == 0) o.integration = ContactIntegration::Nodes;
    ContinueCellTerms t;
    continueCellTerms(s, masters, o, t);
    bool nearSwitch = false;
    int contact = 0;
    for (const auto& p : t.points) {
      nearSwitch = nearSwitch || std::abs(p.gap) < 1e-5;
      contact += p.status == PointStatus::Contact;
      EXPECT_EQ(p.status == PointStatus::Contact, p.gap <= 0);  // the penalised criterion
      EXPECT_EQ(p.augmented, o.penalty * p.gap);
    }
    if (nearSwitch) continue;
    SCOPED_TRACE(k);
    if (!checkTangent(s, masters, o)) continue;
    ++checked;
    mixed += contact > 0 && contact < static_cast<int>(t.points.size());
  }
  EXPECT_GE(checked, 25);
  EXPECT_GE(mixed, 3);
}

TEST(ContinuePenalised, FlatMasterHandCase) {
  // Master y = 0 (normal +Y); SEG2 slave of reference length 2 penetrating by
  // d everywhere, LAGS_C = kappa * (-d): the LAGS_C rows int L_v (g - lambda /
  // kappa) vanish, the slave nodes get lambda * L0/2 * n_m each.
  const std::vector<Segment> masters = {Segment::seg2({2, 0}, {-1, 0})};
  SlaveCell s;
  s.type = CellType::SEG2;
  s.reference.row(0) << 0, -1;
  s.reference.row(1) << 2, -1;
  const double d = 2e-3, kappa = 300.0;
  s.current.row(0) << 0, -d;
  s.current.row(1) << 1, -d;
  s.lagsC << -kappa * d, -kappa * d, 0;
  ContinueOptions o;
  o.penalty = kappa;
  ContinueCellTerms t;
  continueCellTerms(s, masters, o, t);
  for (const auto& p : t.points) EXPECT_EQ(p.status, PointStatus::Contact);
  EXPECT_NEAR(t.residual.segment<2>(t.lagrangeOffset).norm(), 0, 1e-15);
  EXPECT_NEAR(t.residual(1), -kappa * d, 1e-13);
  EXPECT_NEAR(t.residual(3), -kappa * d, 1e-13);
  // Separated (above the master): -int L_v lambda / kappa, the mass matrix of
  // the linear L on a length 2: [2/3 1/3; 1/3 2/3].
  s.current.col(1).setConstant(d);
  s.lagsC << -3, 6, 0;
  continueCellTerms(s, masters, o, t);
  for (const auto& p : t.points) EXPECT_EQ(p.status, PointStatus::Separated);
  EXPECT_NEAR(t.residual(t.lagrangeOffset), -(2.0 / 3 * -3 + 1.0 / 3 * 6) / kappa, 1e-15);
  EXPECT_NEAR(t.residual(t.lagrangeOffset + 1), -(1.0 / 3 * -3 + 2.0 / 3 * 6) / kappa, 1e-15);
  o.penalty = -1;
  EXPECT_THROW(continueCellTerms(s, masters, o, t), aster::Error);
}

TEST(ContinueForcedStatus, OverridesTheCriterionOfPairedPoints) {
  // CONTACT_INIT: a separated cell forced into contact and a penetrating one
  // forced apart; unpaired points stay unpaired.
  const std::vector<Segment> masters = {Segment::seg2({2, 0}, {-1, 0})};
  SlaveCell s;
  s.type = CellType::SEG2;
  s.reference.row(0) << 0, 0;
  s.reference.row(1) << 1, 0;
  s.current = s.reference;
  s.current.col(1).setConstant(0.1);
  ContinueOptions o;
  ContinueCellTerms t;
  o.forcedStatus = ForcedStatus::Contact;
  continueCellTerms(s, masters, o, t);
  for (const auto& p : t.points) EXPECT_EQ(p.status, PointStatus::Contact);
  EXPECT_NEAR(t.residual(t.lagrangeOffset), 0.1 * 0.5, 1e-15);  // int L_1 g
  s.current.col(1).setConstant(-0.1);
  o.forcedStatus = ForcedStatus::Separated;
  continueCellTerms(s, masters, o, t);
  for (const auto& p : t.points) EXPECT_EQ(p.status, PointStatus::Separated);
  EXPECT_EQ(t.residual.norm(), 0.0);  // lambda = 0
  s.current.col(0).array() += 10;  // far from the master
  o.forcedStatus = ForcedStatus::Contact;
  continueCellTerms(s, masters, o, t);
  for (const auto& p : t.points) EXPECT_EQ(p.status, PointStatus::Unpaired);
}

// A slave cell over a groove of two master segments sharing the node (0, 0)
// (contact/vertex_blend.hpp): its middle Gauss point above the vertex, first
// where it projects inside both segments (the blended gap), then HELD at the
// vertex (every point). The tangent against central finite differences of
// the residual; the shared node moved as one (its two copies in the layout,
// one per segment block, together: the sum of their columns and rows).
TEST(Continue, TangentAtAMasterKink) {
  const std::vector<Segment> masters = {Segment::seg2({0, 0}, {-1, 0.2}), Segment::seg2({1, 0.2}, {0, 0})};
  SlaveCell s;
  s.type = CellType::SEG2;
  s.reference << -0.5, 0, 0.5, 0, 0, 0;
  s.current << -0.5, 0.11, 0.5, 0.1, 0, 0;  // slightly tilted: the middle point off the bisector
  s.lagsC << -2.0, -1.5, 0;
  ContinueOptions o;
  o.rho = 10;
  for (int mode = 0; mode < 2; ++mode) {
    if (mode == 1) s.held.assign(3, {0, 1});
    ContinueCellTerms t0, tp, tm;
    continueCellTerms(s, masters, o, t0);
    ASSERT_EQ(t0.points[1].status, PointStatus::Contact);
    const int n = t0.size();  // 4 slave + 4 + 4 master + 2 LAGS_C
    ASSERT_EQ(n, 14);
    // Independent variables: slave (0..3), A's far node (6, 7), B's far node
    // (8, 9), the shared node (4, 5 = A's copy; 10, 11 = B's), LAGS_C (12, 13).
    const std::vector<std::vector<int>> vars = {{0}, {1}, {2}, {3}, {6}, {7}, {8}, {9}, {4, 10}, {5, 11}, {12}, {13}};
    auto apply = [&](const std::vector<int>& v, double h, SlaveCell& sc, std::vector<Segment>& m) {
      for (int d : v) {
        if (d < 4) sc.current(d / 2, d % 2) += h;
        else if (d < 8) m[0].x((d - 4) / 2, d % 2) += h;
        else if (d < 12) m[1].x((d - 8) / 2, d % 2) += h;
        else sc.lagsC(d - 12) += h;
      }
    };
    auto row = [&](const Eigen::VectorXd& r, const std::vector<int>& v) {
      double sum = 0;
      for (int d : v) sum += r(d);
      return sum;
    };
    const double h = 1e-7;
    double worst = 0;
    for (const auto& vj : vars) {
      SlaveCell sp = s, sm = s;
      std::vector<Segment> mp = masters, mm = masters;
      apply(vj, h, sp, mp);
      apply(vj, -h, sm, mm);
      continueCellTerms(sp, mp, o, tp);
      continueCellTerms(sm, mm, o, tm);
      ASSERT_EQ(statuses(tp), statuses(t0));
      for (const auto& vi : vars) {
        const double fd = (row(tp.residual, vi) - row(tm.residual, vi)) / (2 * h);
        double exact = 0;
        for (int i : vi)
          for (int j : vj) exact += t0.tangent(i, j);
        worst = std::max(worst, std::abs(fd - exact));
      }
    }
    EXPECT_LE(worst, 1e-6 * std::max(1.0, t0.tangent.norm())) << "mode " << mode;
  }
}

// Held at the vertex of a symmetric groove, a point off the axis (one Gauss
// point, at x = 0.03, inside B only) has the height above the vertex as its
// gap, and the contact force on the slave is vertical; free, it is B's
// distance and its force along B's normal.
TEST(Continue, HeldPointPushedAlongTheMeanNormal) {
  const std::vector<Segment> masters = {Segment::seg2({0, 0}, {-1, 0.2}), Segment::seg2({1, 0.2}, {0, 0})};
  SlaveCell s;
  s.type = CellType::SEG2;
  s.reference << -0.5, 0, 0.5, 0, 0, 0;
  s.current << -0.47, 0.01, 0.53, 0.01, 0, 0;
  s.lagsC << -3.0, -3.0, 0;
  s.held = {{0, 1}};
  ContinueOptions o;
  o.gaussPoints = 1;
  ContinueCellTerms t;
  continueCellTerms(s, masters, o, t);
  ASSERT_EQ(t.points[0].status, PointStatus::Contact);
  EXPECT_NEAR(t.points[0].gap, 0.01, 1e-15);
  EXPECT_NEAR(t.residual(0), 0, 1e-15);  // slave node 1 x
  EXPECT_NEAR(t.residual(2), 0, 1e-15);  // slave node 2 x
  EXPECT_LT(t.residual(1), 0);           // pushed up: the residual of the force is -f
  s.held.clear();
  continueCellTerms(s, masters, o, t);
  const double c = 1 / std::sqrt(1.04);
  EXPECT_NEAR(t.points[0].gap, (0.01 - 0.2 * 0.03) * c, 1e-15);  // B's line y = 0.2 x
  EXPECT_GT(std::abs(t.residual(0)), 1e-3);
}
