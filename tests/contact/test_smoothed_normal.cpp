// Smoothed master normals (LISSAGE='OUI'): the nodal normal is the mean of
// the cells' normals (hand cases); on a circular arc it converges to the
// radius faster than the facet normal (rates on a smoothly graded mesh: SEG2
// 2 against 1, SEG3 4 against 3); the gap's derivatives
// and the CONTINUE contact tangent with smoothing match central finite
// differences (the tangent is not symmetric: the force acts along the
// smoothed normal); Newton with it converges quadratically, also with slave
// points on the master's vertices.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/LU>

#include "contact/continue_formulation.hpp"
#include "contact/smoothed_normal.hpp"
#include "core/error.hpp"

#include "continue_fixtures.hpp"

using namespace aster::contact;
using namespace aster::contact::testing;
using aster::fem::CellType;
using Eigen::Vector2d;

namespace {

// A master line: nodes and cells (SEG2: 2 nodes; SEG3: ends then middle).
struct Line {
  CellType type = CellType::SEG2;
  std::vector<Vector2d> x;
  std::vector<std::vector<int>> cells;
};

Segment segmentOf(const Line& l, int c) {
  const auto& n = l.cells[c];
  return l.type == CellType::SEG3 ? Segment::seg3(l.x[n[0]], l.x[n[1]], l.x[n[2]]) : Segment::seg2(l.x[n[0]], l.x[n[1]]);
}

// The patch of cell c: its nodes, then those of the cells sharing a node with it.
NormalPatch patchOf(const Line& l, int c) {
  NormalPatch p;
  std::vector<int> ids(l.cells[c]);
  auto index = [&](int node) {
    for (std::size_t i = 0; i < ids.size(); ++i)
      if (ids[i] == node) return static_cast<int>(i);
    ids.push_back(node);
    return static_cast<int>(ids.size()) - 1;
  };
  for (std::size_t a = 0; a < l.cells[c].size(); ++a)
    for (const auto& e : l.cells)
      for (std::size_t b = 0; b < e.size(); ++b)
        if (e[b] == l.cells[c][a]) {
          NormalPatch::Facet f;
          f.type = l.type;
          for (std::size_t k = 0; k < e.size(); ++k) f.node[k] = index(e[k]);
          f.xi = b == 0 ? -1.0 : b == 1 ? 1.0 : 0.0;
          p.facets[a].push_back(f);
        }
  for (int i : ids) p.nodes.push_back(l.x[i]);
  return p;
}

// n cells on the unit circle from angle 0 to pi/2, counterclockwise (normal
// outward, (cos, sin)), graded smoothly: theta(s) = pi/2 (1.3 s - 0.3 s^2).
Line arc(CellType type, int n) {
  Line l;
  l.type = type;
  auto theta = [](double s) { return M_PI / 2 * (1.3 * s - 0.3 * s * s); };
  auto at = [](double t) { return Vector2d(std::cos(t), std::sin(t)); };
  for (int k = 0; k <= n; ++k) l.x.push_back(at(theta(double(k) / n)));
  for (int k = 0; k < n; ++k) {
    if (type == CellType::SEG3) {
      l.x.push_back(at(0.5 * (theta(double(k) / n) + theta(double(k + 1) / n))));
      l.cells.push_back({k, k + 1, static_cast<int>(l.x.size()) - 1});
    } else {
      l.cells.push_back({k, k + 1});
    }
  }
  return l;
}

double angle(const Vector2d& a, const Vector2d& b) {
  return std::abs(std::atan2(a(0) * b(1) - a(1) * b(0), a.dot(b)));
}

struct ArcErrors {
  double smoothedAtNodes = 0, facetAtNodes = 0;  // at the vertices shared by two cells
  double smoothedInside = 0, facetInside = 0;    // at points of the cells away from the arc's ends
};

// Errors of the normals against the radius through the node, or through the
// point of the cell (the circle's normal at its closest point).
ArcErrors arcErrors(CellType type, int n) {
  const Line l = arc(type, n);
  ArcErrors e;
  for (int c = 1; c + 1 < n; ++c) {
    const Segment s = segmentOf(l, c);
    const NormalPatch p = patchOf(l, c);
    const Vector2d x0 = l.x[l.cells[c][0]];
    const Vector2d n0 = smoothedNodeNormal(p, 0);
    e.smoothedAtNodes = std::max(e.smoothedAtNodes, angle(n0, x0));
    e.facetAtNodes = std::max(e.facetAtNodes, angle(segmentFrame(s, -1).normal, x0));
    e.facetAtNodes = std::max(e.facetAtNodes, angle(segmentFrame(segmentOf(l, c - 1), 1).normal, x0));
    for (double xi = -1; xi <= 1; xi += 0.25) {
      const Vector2d x = segmentFrame(s, xi).point;
      e.smoothedInside = std::max(e.smoothedInside, angle(smoothedNormal(s, p, xi), x));
      e.facetInside = std::max(e.facetInside, angle(segmentFrame(s, xi).normal, x));
    }
  }
  return e;
}

}  // namespace

TEST(SmoothedNormal, NodeNormalIsTheMeanOfTheCellsNormals) {
  // A corner: cell 0 from (1,-1) to (1,0) (normal +X), cell 1 from (1,0) to (0,0) (normal +Y).
  Line l;
  l.x = {{1, -1}, {1, 0}, {0, 0}};
  l.cells = {{0, 1}, {1, 2}};
  const NormalPatch p = patchOf(l, 1);
  ASSERT_EQ(p.nodes.size(), 3u);
  EXPECT_NEAR((smoothedNodeNormal(p, 0) - Vector2d(1, 1) / std::sqrt(2.0)).norm(), 0, 1e-15);
  EXPECT_NEAR((smoothedNodeNormal(p, 1) - Vector2d(0, 1)).norm(), 0, 1e-15);  // an end: its one cell's
  // Inside the cell: the normalised interpolation of the nodes' normals.
  const Segment s = segmentOf(l, 1);
  const Vector2d m = 0.75 * Vector2d(1, 1) / std::sqrt(2.0) + 0.25 * Vector2d(0, 1);
  EXPECT_NEAR((smoothedNormal(s, p, -0.5) - m.normalized()).norm(), 0, 1e-15);
  // The mean of unit normals, not of tangents: a long cell weighs as a short one.
  l.x[0] = {1, -100};
  EXPECT_NEAR((smoothedNodeNormal(patchOf(l, 1), 0) - Vector2d(1, 1) / std::sqrt(2.0)).norm(), 0, 1e-15);
  // SEG3: the middle node belongs to its cell alone; a vertex averages the two
  // cells' normals there (each the normal of the parabola at its end).
  Line q;
  q.type = CellType::SEG3;
  q.x = {{2, 0}, {1, 0}, {0, 0}, {1.5, 0.1}, {0.5, 0}};
  q.cells = {{0, 1, 3}, {1, 2, 4}};
  const NormalPatch pq = patchOf(q, 1);
  const Vector2d nEnd = segmentFrame(segmentOf(q, 0), 1).normal, nStart = segmentFrame(segmentOf(q, 1), -1).normal;
  EXPECT_NEAR((smoothedNodeNormal(pq, 0) - (nEnd + nStart).normalized()).norm(), 0, 1e-15);
  EXPECT_NEAR((smoothedNodeNormal(pq, 2) - Vector2d(0, 1)).norm(), 0, 1e-15);
  EXPECT_GT(angle(nEnd, nStart), 0.1);  // the two cells' normals differ there
  // Two cells walked against each other: their normals cancel, refused.
  Line bad;
  bad.x = {{0, 0}, {1, 0}, {2, 0}};
  bad.cells = {{0, 1}, {2, 1}};
  EXPECT_THROW(smoothedNodeNormal(patchOf(bad, 0), 1), aster::Error);
}

TEST(SmoothedNormal, ConvergesToTheRadiusFasterThanTheFacetNormal) {
  for (CellType type : {CellType::SEG2, CellType::SEG3}) {
    SCOPED_TRACE(type == CellType::SEG2 ? "SEG2" : "SEG3");
    std::vector<ArcErrors> e;
    for (int n : {8, 16, 32, 64}) e.push_back(arcErrors(type, n));
    for (std::size_t i = 0; i + 1 < e.size(); ++i) {
      const double smoothNode = std::log2(e[i].smoothedAtNodes / e[i + 1].smoothedAtNodes);
      const double facetNode = std::log2(e[i].facetAtNodes / e[i + 1].facetAtNodes);
      const double smoothIn = std::log2(e[i].smoothedInside / e[i + 1].smoothedInside);
      const double facetIn = std::log2(e[i].facetInside / e[i + 1].facetInside);
      std::printf("%s n=%d: node error smoothed %.3e (rate %.2f) facet %.3e (rate %.2f); inside smoothed %.3e (rate %.2f) facet %.3e (rate %.2f)\n",
                  type == CellType::SEG2 ? "SEG2" : "SEG3", 8 << i, e[i].smoothedAtNodes, smoothNode,
                  e[i].facetAtNodes, facetNode, e[i].smoothedInside, smoothIn, e[i].facetInside, facetIn);
      if (type == CellType::SEG2) {
        EXPECT_NEAR(facetNode, 1.0, 0.1);
        EXPECT_NEAR(facetIn, 1.0, 0.1);
        EXPECT_NEAR(smoothNode, 2.0, 0.15);
        EXPECT_NEAR(smoothIn, 2.0, 0.15);
      } else {
        // The parabola through three points of the circle: its normal is off by O(h^3).
        EXPECT_NEAR(facetNode, 3.0, 0.15);
        EXPECT_NEAR(facetIn, 3.0, 0.3);
        EXPECT_NEAR(smoothNode, 4.0, 0.15);
        EXPECT_NEAR(smoothIn, 4.0, 0.15);
      }
      EXPECT_LT(e[i].smoothedAtNodes, e[i].facetAtNodes);
      EXPECT_LT(e[i].smoothedInside, e[i].facetInside);
    }
  }
}

namespace {

// Four cells on y = parabola(x), walked from x = 2 to x = -1 (normal ~ +Y),
// the nodes moved by up to `noise`.
Line curvedMaster(CellType type, std::mt19937& gen, double noise) {
  std::uniform_real_distribution<double> u(-1, 1);
  Line l;
  l.type = type;
  auto at = [&](double x) { return Vector2d(x + noise * u(gen), parabola(x) + noise * u(gen)); };
  for (int k = 0; k <= 4; ++k) l.x.push_back(at(2.0 - 0.75 * k));
  for (int k = 0; k < 4; ++k) {
    if (type == CellType::SEG3) {
      l.x.push_back(at(2.0 - 0.75 * (k + 0.5)));
      l.cells.push_back({k, k + 1, static_cast<int>(l.x.size()) - 1});
    } else {
      l.cells.push_back({k, k + 1});
    }
  }
  return l;
}

}  // namespace

TEST(SmoothedNormal, GapDerivativesMatchFiniteDifferences) {
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> u(-1, 1);
  int checked = 0, clamped = 0;
  double neighbours = 0;  // largest |dg/d(nodes of the neighbour cells)|
  for (int k = 0; k < 40; ++k) {
    const Line l = curvedMaster(k % 2 ? CellType::SEG3 : CellType::SEG2, gen, 0.05);
    const int c = 1 + k % 2;
    const Segment s = segmentOf(l, c);
    const NormalPatch p = patchOf(l, c);
    // Points off the cell by 0.02 to 0.08 either side, some past its ends (clamped projections).
    const double xi = k % 5 == 0 ? (k % 2 ? 1.1 : -1.1) : 0.9 * u(gen);
    const auto frame = segmentFrame(s, std::clamp(xi, -1.0, 1.0));
    const double off = u(gen);
    const Vector2d xs = frame.point + 0.2 * (xi - std::clamp(xi, -1.0, 1.0)) * frame.tangent +
                        (off > 0 ? 0.02 + 0.06 * off : -0.02 + 0.06 * off) * frame.normal;
    ProjectionOptions po;
    po.outsideTolerance = 0.5;
    const Projection pr = projectOnSegment(xs, s, po);
    if (pr.status == ProjectionStatus::Outside) continue;
    clamped += pr.status == ProjectionStatus::Clamped;
    const SmoothedGap g = linearizeSmoothedGap(xs, s, p, pr);
    // q = (x_s, patch nodes) -> g with the projection redone (held at the end when clamped).
    auto gapAt = [&](const Eigen::VectorXd& q, Eigen::VectorXd* grad) {
      NormalPatch pq = p;
      for (std::size_t j = 0; j < p.nodes.size(); ++j) pq.nodes[j] = q.segment<2>(2 + 2 * j);
      Segment sq = s;
      for (int a = 0; a < s.nodes(); ++a) sq.x.row(a) = pq.nodes[a].transpose();
      const Projection pp = projectOnSegment(q.head<2>(), sq, po);
      EXPECT_EQ(pp.status, pr.status);
      if (grad) *grad = linearizeSmoothedGap(q.head<2>(), sq, pq, pp).gradient;
      return smoothedGap(q.head<2>(), sq, pq, pp.xi);
    };
    Eigen::VectorXd q(2 + 2 * p.nodes.size());
    q.head<2>() = xs;
    for (std::size_t j = 0; j < p.nodes.size(); ++j) q.segment<2>(2 + 2 * j) = p.nodes[j];
    ASSERT_EQ(g.gradient.size(), q.size());
    EXPECT_NEAR(g.gap, gapAt(q, nullptr), 1e-15);
    const double h = 1e-6;
    Eigen::VectorXd fd(q.size());
    Eigen::MatrixXd fdH(q.size(), q.size());
    for (int j = 0; j < q.size(); ++j) {
      Eigen::VectorXd qp = q, qm = q, gp, gm;
      qp(j) += h;
      qm(j) -= h;
      fd(j) = (gapAt(qp, &gp) - gapAt(qm, &gm)) / (2 * h);
      fdH.col(j) = (gp - gm) / (2 * h);
    }
    EXPECT_LE((g.gradient - fd).norm(), 1e-8 * (1 + g.gradient.norm())) << g.gradient.transpose() << "\n" << fd.transpose();
    EXPECT_LE((g.hessian - fdH).norm(), 1e-6 * (1 + g.hessian.norm())) << g.hessian << "\n\n" << fdH;
    EXPECT_LE((g.hessian - g.hessian.transpose()).norm(), 1e-12 * (1 + g.hessian.norm()));
    neighbours = std::max(neighbours, g.gradient.tail(2 * (p.nodes.size() - s.nodes())).norm());
    ++checked;
  }
  EXPECT_GE(checked, 35);
  EXPECT_GE(clamped, 4);
  EXPECT_GT(neighbours, 1e-3);  // the normal depends on them
}

namespace {

// Cell DOFs <-> (slave current coordinates, every candidate's patch nodes, LAGS_C);
// each segment's nodes are its patch's first ones.
Eigen::VectorXd pack(const SlaveCell& s, const std::vector<NormalPatch>& patches, int nm) {
  std::vector<double> v;
  const int ns = s.type == CellType::SEG3 ? 3 : 2;
  for (int a = 0; a < ns; ++a) v.push_back(s.current(a, 0)), v.push_back(s.current(a, 1));
  for (const auto& p : patches)
    for (const auto& x : p.nodes) v.push_back(x(0)), v.push_back(x(1));
  for (int a = 0; a < nm; ++a) v.push_back(s.lagsC(a));
  return Eigen::Map<Eigen::VectorXd>(v.data(), v.size());
}

void unpack(const Eigen::VectorXd& q, SlaveCell& s, std::vector<Segment>& masters, std::vector<NormalPatch>& patches,
            int nm) {
  int k = 0;
  const int ns = s.type == CellType::SEG3 ? 3 : 2;
  for (int a = 0; a < ns; ++a) s.current(a, 0) = q(k++), s.current(a, 1) = q(k++);
  for (std::size_t m = 0; m < patches.size(); ++m) {
    for (auto& x : patches[m].nodes) x(0) = q(k++), x(1) = q(k++);
    for (int a = 0; a < masters[m].nodes(); ++a) masters[m].x.row(a) = patches[m].nodes[a].transpose();
  }
  for (int a = 0; a < nm; ++a) s.lagsC(a) = q(k++);
}

bool checkTangent(const SlaveCell& s, const std::vector<Segment>& masters, const std::vector<NormalPatch>& patches,
                  const ContinueOptions& o) {
  ContinueCellTerms t0, tp, tm;
  continueCellTerms(s, masters, o, t0, &patches);
  const int nm = multiplierCount(s, o);
  const Eigen::VectorXd q = pack(s, patches, nm);
  EXPECT_EQ(q.size(), t0.size());
  const double h = 1e-7;
  Eigen::MatrixXd fd(q.size(), q.size());
  for (int j = 0; j < q.size(); ++j) {
    Eigen::VectorXd qp = q, qm = q;
    qp(j) += h;
    qm(j) -= h;
    SlaveCell sp = s, sm = s;
    std::vector<Segment> mp = masters, mm = masters;
    std::vector<NormalPatch> pp = patches, pm = patches;
    unpack(qp, sp, mp, pp, nm);
    unpack(qm, sm, mm, pm, nm);
    continueCellTerms(sp, mp, o, tp, &pp);
    continueCellTerms(sm, mm, o, tm, &pm);
    if (statuses(tp) != statuses(t0) || statuses(tm) != statuses(t0)) return false;
    fd.col(j) = (tp.residual - tm.residual) / (2 * h);
  }
  const double scale = std::max(1.0, t0.tangent.norm());
  EXPECT_LE((t0.tangent - fd).norm(), 1e-6 * scale) << "tangent\n" << t0.tangent << "\nfd\n" << fd;
  return true;
}

}  // namespace

TEST(SmoothedNormal, ContinueTangentMatchesFiniteDifferences) {
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-1, 1);
  int checked = 0, mixed = 0, split = 0;
  for (int k = 0; k < 60; ++k) {
    const Line l = curvedMaster(k % 4 < 2 ? CellType::SEG3 : CellType::SEG2, gen, 0.01);
    // The slave spans the node x = 0.5 between master cells 1 and 2.
    SlaveCell s = slaveAlong(k % 2 ? CellType::SEG3 : CellType::SEG2, 0.2 + 0.1 * u(gen), 0.8 + 0.1 * u(gen), gen, 0.01);
    s.lagsC << 0.5 * u(gen) - 0.2, 0.5 * u(gen) - 0.2, 0.5 * u(gen) - 0.2;
    std::vector<Segment> masters = {segmentOf(l, 1), segmentOf(l, 2)};
    std::vector<NormalPatch> patches = {patchOf(l, 1), patchOf(l, 2)};
    ContinueOptions o;
    o.rho = k % 4 ? 100 : 3;
    o.gaussPoints = 3 + k % 2;
    if (k % 3 == 0) o.multiplierInterpolation = MultiplierInterpolation::Quadratic;
    if (k % 5 == 0) o.integration = ContactIntegration::Nodes;
    if (k % 7 == 0) o.penalty = 50;
    ContinueCellTerms t;
    continueCellTerms(s, masters, o, t, &patches);
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
    if (!checkTangent(s, masters, patches, o)) continue;
    ++checked;
    mixed += contact > 0 && contact < static_cast<int>(t.points.size());
    split += segs.front() != segs.back();
  }
  EXPECT_GE(checked, 40);
  EXPECT_GE(mixed, 5);
  EXPECT_GE(split, 10);
}

namespace {

// A slave cell pulled by springs (stiffness 2) from its current position
// towards `anchor`, against fixed master cells with LISSAGE: slave DOFs and
// LAGS_C solved by Newton with the cell's tangent. Returns the residual norms.
std::vector<double> springNewton(SlaveCell& s, const Eigen::Matrix<double, 3, 2>& anchor,
                                 const std::vector<Segment>& masters, const std::vector<NormalPatch>& patches,
                                 const ContinueOptions& o, ContinueCellTerms& t) {
  const double k = 2.0;
  const int ns = s.type == CellType::SEG3 ? 3 : 2;
  const int nm = multiplierCount(s, o);
  const int nf = 2 * ns + nm;
  std::vector<double> norms;
  for (int it = 0; it < 30; ++it) {
    continueCellTerms(s, masters, o, t, &patches);
    Eigen::VectorXd R(nf);
    Eigen::MatrixXd K(nf, nf);
    std::vector<int> idx;
    for (int i = 0; i < 2 * ns; ++i) idx.push_back(i);
    for (int v = 0; v < nm; ++v) idx.push_back(t.lagrangeOffset + v);
    for (int i = 0; i < nf; ++i) {
      R(i) = t.residual(idx[i]);
      for (int j = 0; j < nf; ++j) K(i, j) = t.tangent(idx[i], idx[j]);
    }
    for (int a = 0; a < ns; ++a)
      for (int c = 0; c < 2; ++c) {
        R(2 * a + c) += k * (s.current(a, c) - anchor(a, c));
        K(2 * a + c, 2 * a + c) += k;
      }
    norms.push_back(R.norm());
    if (R.norm() < 1e-14) break;
    const Eigen::VectorXd d = K.fullPivLu().solve(-R);
    for (int a = 0; a < ns; ++a) s.current.row(a) += d.segment<2>(2 * a).transpose();
    s.lagsC.head(nm) += d.tail(nm);
  }
  return norms;
}

void expectQuadratic(const std::vector<double>& norms) {
  ASSERT_LT(norms.back(), 1e-14);
  ASSERT_LE(norms.size(), 15u);
  int quadratic = 0;
  for (std::size_t i = 1; i + 1 < norms.size(); ++i)
    if (norms[i] < 1e-2 && norms[i + 1] > 1e-15) {
      EXPECT_LE(norms[i + 1], 100 * norms[i] * norms[i]) << "step " << i;
      ++quadratic;
    }
  EXPECT_GE(quadratic, 1);
}

}  // namespace

TEST(SmoothedNormal, NewtonConvergesQuadraticallyOnASpringLoadedSlave) {
  // A SEG3 slave across the node between two master cells, Gauss points.
  std::mt19937 gen(3);
  const Line l = curvedMaster(CellType::SEG2, gen, 0.0);
  const std::vector<Segment> masters = {segmentOf(l, 1), segmentOf(l, 2)};
  const std::vector<NormalPatch> patches = {patchOf(l, 1), patchOf(l, 2)};
  SlaveCell s;
  s.type = CellType::SEG3;
  s.reference << 0.1, 0, 0.9, 0, 0.5, 0;
  Eigen::Matrix<double, 3, 2> anchor;
  anchor << 0.12, -0.08, 0.93, -0.06, 0.52, -0.05;
  s.current << 0.1, 0.02, 0.9, 0.02, 0.5, 0.03;
  ContinueOptions o;
  o.rho = 10;
  ContinueCellTerms t;
  expectQuadratic(springNewton(s, anchor, masters, patches, o, t));
  // In contact, compressive: the weighted gaps int L_v g vanish (R ~ 0), not each point's.
  for (const auto& p : t.points) {
    EXPECT_EQ(p.status, PointStatus::Contact);
    EXPECT_LT(p.pressure, 0);
  }
}

TEST(SmoothedNormal, NewtonConvergesWithSlavePointsOnMasterVertices) {
  // A SEG2 slave from the master node x = 0.5 to the node x = 1.25, integrated
  // at its nodes (INTEGRATION='AUTO'): both points sit on master vertices,
  // where the cells' own normals differ. The force along the smoothed normal
  // keeps them from sliding to and fro across the vertices.
  std::mt19937 gen(3);
  const Line l = curvedMaster(CellType::SEG2, gen, 0.0);
  const std::vector<Segment> masters = {segmentOf(l, 0), segmentOf(l, 1), segmentOf(l, 2)};
  const std::vector<NormalPatch> patches = {patchOf(l, 0), patchOf(l, 1), patchOf(l, 2)};
  SlaveCell s;
  s.type = CellType::SEG2;
  s.reference.row(0) = l.x[2].transpose();
  s.reference.row(1) = l.x[1].transpose();
  s.current = s.reference;
  Eigen::Matrix<double, 3, 2> anchor = s.reference;
  anchor.col(1).array() -= 0.05;  // pulled into the master
  anchor(0, 0) += 0.01;           // and a little along it
  ContinueOptions o;
  o.rho = 10;
  o.integration = ContactIntegration::Nodes;
  ContinueCellTerms t;
  expectQuadratic(springNewton(s, anchor, masters, patches, o, t));
  for (const auto& p : t.points) {
    EXPECT_EQ(p.status, PointStatus::Contact);
    EXPECT_LT(p.pressure, 0);
    EXPECT_NEAR(p.gap, 0, 1e-14);  // two nodes, two LAGS_C: each point's gap closes
  }
}
