// The blended gap at a master kink (vertex_blend.hpp): its variations against
// central finite differences (straight and curved segments, every variable
// including each segment's copy of the shared node), its value and variation
// on the bisector of a symmetric groove (the distance, the mean normal), C1
// continuity with the single segment's gap where the region ends, and which
// segments are partners.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/vertex_blend.hpp"
#include "core/error.hpp"

using namespace aster::contact;
using aster::fem::CellType;
using Eigen::Vector2d;

namespace {

// A groove: A = (0,0) -> (-1, s), B = (1, s) -> (0,0) (walked right to left,
// normals up, tilted towards the axis), sharing the vertex (0,0).
std::vector<Segment> groove(double s) {
  return {Segment::seg2({0, 0}, {-1, s}), Segment::seg2({1, s}, {0, 0})};
}

// q = (x_s, A's nodes, B's nodes) <-> the point and the two segments.
Eigen::VectorXd pack(const Vector2d& xs, const Segment& a, const Segment& b) {
  Eigen::VectorXd q(2 + 2 * a.nodes() + 2 * b.nodes());
  q.head(2) = xs;
  int k = 2;
  for (const Segment* s : {&a, &b})
    for (int n = 0; n < s->nodes(); ++n) q(k++) = s->x(n, 0), q(k++) = s->x(n, 1);
  return q;
}
void unpack(const Eigen::VectorXd& q, Vector2d& xs, Segment& a, Segment& b) {
  xs = q.head(2);
  int k = 2;
  for (Segment* s : {&a, &b})
    for (int n = 0; n < s->nodes(); ++n) s->x(n, 0) = q(k++), s->x(n, 1) = q(k++);
}
VertexBlendGap blendAt(const Eigen::VectorXd& q, Segment a, Segment b) {
  Vector2d xs;
  unpack(q, xs, a, b);
  const Projection pa = projectOnSegment(xs, a), pb = projectOnSegment(xs, b);
  EXPECT_EQ(pa.status, ProjectionStatus::Inside);
  EXPECT_EQ(pb.status, ProjectionStatus::Inside);
  return blendVertexGaps(linearizeGap(xs, a, pa), linearizeGap(xs, b, pb));
}

void checkAgainstFiniteDifferences(const Vector2d& xs, const Segment& a, const Segment& b) {
  const Eigen::VectorXd q = pack(xs, a, b);
  const VertexBlendGap g0 = blendAt(q, a, b);
  ASSERT_EQ(g0.gradient.size(), q.size());
  const double h = 1e-6;
  Eigen::VectorXd fdGradient(q.size());
  Eigen::MatrixXd fdHessian(q.size(), q.size());
  for (int j = 0; j < q.size(); ++j) {
    Eigen::VectorXd qp = q, qm = q;
    qp(j) += h;
    qm(j) -= h;
    const VertexBlendGap gp = blendAt(qp, a, b), gm = blendAt(qm, a, b);
    fdGradient(j) = (gp.gap - gm.gap) / (2 * h);
    fdHessian.col(j) = (gp.gradient - gm.gradient) / (2 * h);
  }
  EXPECT_LE((g0.gradient - fdGradient).norm(), 1e-7 * std::max(1.0, g0.gradient.norm()));
  EXPECT_LE((g0.hessian - fdHessian).norm(), 1e-6 * std::max(1.0, g0.hessian.norm()))
      << "hessian\n" << g0.hessian << "\nfd\n" << fdHessian;
  EXPECT_LE((g0.hessian - g0.hessian.transpose()).norm(), 1e-12 * std::max(1.0, g0.hessian.norm()));
}

}  // namespace

TEST(VertexBlend, VariationsMatchFiniteDifferences) {
  const auto m = groove(0.2);
  // Above the groove, off the bisector, both projections inside.
  checkAgainstFiniteDifferences(Vector2d(0.005, 0.05), m[0], m[1]);
  checkAgainstFiniteDifferences(Vector2d(-0.004, 0.3), m[0], m[1]);
  // Curved segments (SEG3) sharing the vertex; a ridge, the point below it.
  const Segment a = Segment::seg3({0, 0}, {-1, -0.3}, {-0.5, -0.1});
  const Segment b = Segment::seg3({1, -0.2}, {0, 0}, {0.5, -0.05});
  checkAgainstFiniteDifferences(Vector2d(0.002, -0.03), a, b);
  const Segment c = Segment::seg3({0, 0}, {-1, 0.3}, {-0.5, 0.1});
  const Segment d = Segment::seg3({1, 0.2}, {0, 0}, {0.5, 0.12});
  checkAgainstFiniteDifferences(Vector2d(0.01, 0.2), c, d);
}

TEST(VertexBlend, OnTheBisectorTheDistanceAndTheMeanNormal) {
  const double s = 0.2, y = 0.05;
  const auto m = groove(s);
  const Vector2d xs(0, y);
  Projection partner;
  const MasterProjection mp = projectOnMaster(xs, m);
  ASSERT_TRUE(mp.paired());
  const int b = vertexPartner(xs, m, mp.segment, mp.projection, {}, partner);
  ASSERT_EQ(b, 1 - mp.segment);
  const VertexBlendGap g = blendVertexGaps(linearizeGap(xs, m[mp.segment], mp.projection),
                                           linearizeGap(xs, m[b], partner));
  // The distance to either line: y cos(atan s) = y / sqrt(1 + s^2).
  const double c = 1 / std::sqrt(1 + s * s);
  EXPECT_NEAR(g.gap, y * c, 1e-15);
  EXPECT_NEAR(g.weight, 0.5, 1e-15);
  // d g / d x_s: the mean of the normals (s, 1) c and (-s, 1) c.
  EXPECT_NEAR(g.gradient(0), 0, 1e-15);
  EXPECT_NEAR(g.gradient(1), c, 1e-15);
  EXPECT_NEAR(pairedGap(xs, m, mp, {}), y * c, 1e-15);
}

TEST(VertexBlend, JoinsTheSingleSegmentGapWithItsVariation) {
  // The region ends where A's projection reaches the vertex: on the ray along
  // A's normal at (0, 0); past it only B is paired. At a distance eps inside,
  // the blend differs from B's gap by O(eps^2) and its variation from B's by
  // O(eps) (w = O(phi_A^2), w' = O(phi_A)): C1.
  const auto m = groove(0.2);
  const Vector2d edge = 0.3 * segmentFrame(m[0], -1).normal;
  const Vector2d tA = segmentFrame(m[0], -1).tangent;  // from the vertex into A
  double gapError[2], slopeError[2];
  for (int k = 0; k < 2; ++k) {
    const double eps = k == 0 ? 1e-3 : 1e-4;
    const Vector2d xs = edge + eps * tA;  // A's projection just inside A
    const Projection pa = projectOnSegment(xs, m[0]), pb = projectOnSegment(xs, m[1]);
    ASSERT_EQ(pa.status, ProjectionStatus::Inside);
    ASSERT_EQ(pb.status, ProjectionStatus::Inside);
    const NodeGap gb = linearizeGap(xs, m[1], pb);
    const VertexBlendGap g = blendVertexGaps(linearizeGap(xs, m[0], pa), gb);
    gapError[k] = std::abs(g.gap - gb.gap);
    slopeError[k] = (g.gradient.head(2) - gb.gradient.head(2)).norm();
  }
  EXPECT_LT(gapError[0], 1e-4);
  EXPECT_GT(gapError[0], 50 * gapError[1]);   // ~ 100: second order
  EXPECT_LT(slopeError[0], 1e-1);
  EXPECT_GT(slopeError[0], 5 * slopeError[1]);  // ~ 10: first order
}

TEST(VertexBlend, PartnersShareANodeAndBothProjectInside) {
  const auto m = groove(0.2);
  Projection partner;
  // Above the vertex: partners.
  const MasterProjection above = projectOnMaster(Vector2d(0.001, 0.1), m);
  EXPECT_EQ(vertexPartner(Vector2d(0.001, 0.1), m, above.segment, above.projection, {}, partner), 0);
  // Far along B: B's projection inside, A's clamped past its end: none.
  const MasterProjection onB = projectOnMaster(Vector2d(0.5, 0.2), m);
  ASSERT_EQ(onB.segment, 1);
  EXPECT_EQ(vertexPartner(Vector2d(0.5, 0.2), m, onB.segment, onB.projection, {}, partner), -1);
  EXPECT_EQ(pairedGap(Vector2d(0.5, 0.2), m, onB, {}), onB.projection.gap);
  // Below the groove's vertex both projections are clamped: none.
  const MasterProjection below = projectOnMaster(Vector2d(0.0, -0.01), m);
  EXPECT_EQ(vertexPartner(Vector2d(0.0, -0.01), m, below.segment, below.projection, {}, partner), -1);
  // Two segments that share no node: none, even when both project inside.
  const std::vector<Segment> apart = {Segment::seg2({0, 0}, {-1, 0.2}), Segment::seg2({1, 0.2}, {0.0, 1e-9})};
  const MasterProjection mp = projectOnMaster(Vector2d(0.0, 0.1), apart);
  EXPECT_EQ(vertexPartner(Vector2d(0.0, 0.1), apart, mp.segment, mp.projection, {}, partner), -1);
}

TEST(VertexHold, VariationsMatchFiniteDifferences) {
  // Variables moved one at a time: x_s, every node of A (its copy of the
  // shared node included) and every node of B but its copy of the shared
  // node (moving it alone would unshare them); straight and curved.
  const std::vector<std::pair<Segment, Segment>> pairs = {
      {Segment::seg2({0, 0}, {-1, 0.2}), Segment::seg2({1, 0.3}, {0, 0})},
      {Segment::seg3({0, 0}, {-1, -0.3}, {-0.5, -0.1}), Segment::seg3({1, -0.2}, {0, 0}, {0.5, -0.05})}};
  for (const auto& [a, b] : pairs) {
    const Vector2d xs(0.03, -0.02);
    const Eigen::VectorXd q = pack(xs, a, b);
    const VertexBlendGap g0 = heldVertexGap(xs, a, b);
    ASSERT_EQ(g0.gradient.size(), q.size());
    const int sharedB = 2 + 2 * a.nodes() + 2;  // B's node 2 (index 1) is the shared one in both pairs
    const double h = 1e-6;
    for (int j = 0; j < q.size(); ++j) {
      if (j == sharedB || j == sharedB + 1) continue;
      Eigen::VectorXd qp = q, qm = q;
      qp(j) += h;
      qm(j) -= h;
      Segment ap = a, am = a, bp = b, bm = b;
      Vector2d xp, xm;
      unpack(qp, xp, ap, bp);
      unpack(qm, xm, am, bm);
      if (j == 2 || j == 3) bp.x.row(1) = ap.x.row(0), bm.x.row(1) = am.x.row(0);  // A's node 1 is the shared one
      // The shared node moved through A's copy: its derivative is the sum of both copies'.
      const int k = (j == 2 || j == 3) ? sharedB + (j - 2) : -1;
      const VertexBlendGap gp = heldVertexGap(xp, ap, bp), gm = heldVertexGap(xm, am, bm);
      const double fd = (gp.gap - gm.gap) / (2 * h);
      const double exact = g0.gradient(j) + (k >= 0 ? g0.gradient(k) : 0.0);
      EXPECT_NEAR(fd, exact, 1e-8) << "variable " << j;
      Eigen::VectorXd fdRow = (gp.gradient - gm.gradient) / (2 * h);
      Eigen::VectorXd exactRow = g0.hessian.col(j) + (k >= 0 ? Eigen::VectorXd(g0.hessian.col(k)) : Eigen::VectorXd::Zero(q.size()));
      for (int r = 0; r < q.size(); ++r) {
        if (r == sharedB || r == sharedB + 1) continue;  // B's copy: compared through A's
        const int rk = (r == 2 || r == 3) ? sharedB + (r - 2) : -1;
        const double fdr = fdRow(r) + (rk >= 0 ? fdRow(rk) : 0.0);
        const double exr = exactRow(r) + (rk >= 0 ? exactRow(rk) : 0.0);
        EXPECT_NEAR(fdr, exr, 1e-6) << "variables " << r << ", " << j;
      }
    }
    EXPECT_LE((g0.hessian - g0.hessian.transpose()).norm(), 1e-12);
  }
}

TEST(VertexHold, TheMeanNormalAtTheVertex) {
  // A symmetric groove: the held gap is the height above the vertex, its
  // variation in x_s the vertical, wherever the point is (a line).
  const auto m = groove(0.2);
  for (const Vector2d& xs : {Vector2d(0, 0.05), Vector2d(0.3, -0.01), Vector2d(-0.2, 0.0)}) {
    const VertexBlendGap g = heldVertexGap(xs, m[0], m[1]);
    EXPECT_NEAR(g.gap, xs(1), 1e-15);
    EXPECT_NEAR(g.gradient(0), 0, 1e-15);
    EXPECT_NEAR(g.gradient(1), 1, 1e-15);
  }
  // Segments sharing no node: an error.
  EXPECT_THROW(heldVertexGap(Vector2d(0, 0.1), Segment::seg2({0, 0}, {-1, 0.2}), Segment::seg2({1, 0.2}, {0, 1e-9})),
               aster::Error);
}
