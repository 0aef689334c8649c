// Blended gap at a master kink (formulas in vertex_blend.hpp).
#include "contact/vertex_blend.hpp"

#include <limits>

#include "contact/jet.hpp"

namespace aster::contact {

namespace {

bool shareNode(const Segment& a, const Segment& b) {
  int i, j;
  return sharedVertex(a, b, i, j);
}

// phi = 1 - xi^2 and s = phiA / (phiA + phiB) below a tiny sum: none (both at an end).
bool weightArgument(double xiA, double xiB, double& phiA, double& phiB) {
  phiA = 1 - xiA * xiA;
  phiB = 1 - xiB * xiB;
  return phiA + phiB > 1e-14;
}

}  // namespace

int vertexPartner(const Eigen::Vector2d& xs, const std::vector<Segment>& masters, int nearest,
                  const Projection& nearestProjection, const ProjectionOptions& options, Projection& partner) {
  if (nearest < 0 || nearestProjection.status != ProjectionStatus::Inside) return -1;
  int best = -1;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (int k = 0; k < static_cast<int>(masters.size()); ++k) {
    if (k == nearest || !shareNode(masters[nearest], masters[k])) continue;
    const Projection p = projectOnSegment(xs, masters[k], options);
    if (p.status != ProjectionStatus::Inside || !(p.distance < bestDistance)) continue;
    double phiA, phiB;
    if (!weightArgument(nearestProjection.xi, p.xi, phiA, phiB)) continue;
    best = k;
    bestDistance = p.distance;
    partner = p;
  }
  return best;
}

double vertexBlendWeight(double xiA, double xiB) {
  double phiA, phiB;
  if (!weightArgument(xiA, xiB, phiA, phiB)) return 0.5;
  const double s = phiA / (phiA + phiB);
  return s * s * (3 - 2 * s);
}

VertexBlendGap blendVertexGaps(const NodeGap& a, const NodeGap& b) {
  const int na = static_cast<int>(a.gradient.size()) - 2, nb = static_cast<int>(b.gradient.size()) - 2;
  const int n = 2 + na + nb;
  // A's and B's variables placed in q = (x_s, A's nodes, B's nodes).
  auto vecA = [&](const GapVector& v) {
    Eigen::VectorXd o = Eigen::VectorXd::Zero(n);
    o.head(2) = v.head(2);
    o.segment(2, na) = v.tail(na);
    return o;
  };
  auto vecB = [&](const GapVector& v) {
    Eigen::VectorXd o = Eigen::VectorXd::Zero(n);
    o.head(2) = v.head(2);
    o.segment(2 + na, nb) = v.tail(nb);
    return o;
  };
  auto mat = [&](const GapMatrix& m, int offset, int size) {
    Eigen::MatrixXd o = Eigen::MatrixXd::Zero(n, n);
    o.topLeftCorner(2, 2) = m.topLeftCorner(2, 2);
    o.block(0, offset, 2, size) = m.topRightCorner(2, size);
    o.block(offset, 0, size, 2) = m.bottomLeftCorner(size, 2);
    o.block(offset, offset, size, size) = m.bottomRightCorner(size, size);
    return o;
  };
  const double xiA = a.projection.xi, xiB = b.projection.xi;
  double phiA, phiB;
  if (!weightArgument(xiA, xiB, phiA, phiB))
    throw Error("contact gap: a vertex blend needs a projection inside one of the two segments at least");
  // phi = 1 - xi^2: dphi = -2 xi dxi, d2phi = -2 (dxi dxi^T + xi d2xi).
  const Eigen::VectorXd dxA = vecA(a.xiGradient), dxB = vecB(b.xiGradient);
  const Eigen::VectorXd dpA = -2 * xiA * dxA, dpB = -2 * xiB * dxB;
  const Eigen::MatrixXd hpA = -2 * (dxA * dxA.transpose() + xiA * mat(a.xiHessian, 2, na));
  const Eigen::MatrixXd hpB = -2 * (dxB * dxB.transpose() + xiB * mat(b.xiHessian, 2 + na, nb));
  // s = phiA / (phiA + phiB) and its partial derivatives.
  const double sum = phiA + phiB, s = phiA / sum;
  const double sA = phiB / (sum * sum), sB = -phiA / (sum * sum);
  const double sAA = -2 * phiB / (sum * sum * sum), sBB = 2 * phiA / (sum * sum * sum),
               sAB = (phiA - phiB) / (sum * sum * sum);
  const Eigen::VectorXd ds = sA * dpA + sB * dpB;
  const Eigen::MatrixXd hs = sA * hpA + sB * hpB + sAA * dpA * dpA.transpose() + sBB * dpB * dpB.transpose() +
                             sAB * (dpA * dpB.transpose() + dpB * dpA.transpose());
  // w = S(s) = s^2 (3 - 2 s).
  const double w = s * s * (3 - 2 * s), w1 = 6 * s * (1 - s), w2 = 6 - 12 * s;
  const Eigen::VectorXd dgA = vecA(a.gradient), dgB = vecB(b.gradient), dd = dgA - dgB;
  const Eigen::MatrixXd hgA = mat(a.hessian, 2, na), hgB = mat(b.hessian, 2 + na, nb);
  const double d = a.gap - b.gap;
  VertexBlendGap out;
  out.weight = w;
  out.gap = b.gap + w * d;
  out.gradient = dgB + w * dd + d * w1 * ds;
  out.hessian = hgB + w * (hgA - hgB) + w1 * (ds * dd.transpose() + dd * ds.transpose()) +
                d * (w2 * ds * ds.transpose() + w1 * hs);
  return out;
}

bool sharedVertex(const Segment& a, const Segment& b, int& nodeA, int& nodeB) {
  // The vertices (a middle node is never shared by two master cells).
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      if (a.x.row(i) == b.x.row(j)) {
        nodeA = i;
        nodeB = j;
        return true;
      }
  return false;
}

VertexBlendGap heldVertexGap(const Eigen::Vector2d& xs, const Segment& a, const Segment& b) {
  int ea, eb;
  if (!sharedVertex(a, b, ea, eb)) throw Error("contact gap: a point held at a vertex needs two segments sharing a node");
  constexpr int N = 2 + 2 * 3 + 2 * 3;  // the largest q: two SEG3
  using J = Jet<N>;
  using V = JetVec2<N>;
  const int na = 2 * a.nodes(), nb = 2 * b.nodes();
  const V x{J::variable(xs(0), 0), J::variable(xs(1), 1)};
  // The unit normal (c_y, -c_x) / |c| of segment s at its node e, its nodes the variables from `first` on.
  auto normalAt = [](const Segment& s, int e, int first, V& node) {
    const SegmentShape sh = segmentShape(s.type, e == 0 ? -1.0 : 1.0);
    V c{J::constant(0), J::constant(0)};
    for (int k = 0; k < s.nodes(); ++k) {
      const V y{J::variable(s.x(k, 0), first + 2 * k), J::variable(s.x(k, 1), first + 2 * k + 1)};
      c = c + J::constant(sh.dN(k)) * y;
      if (k == e) node = y;
    }
    const J length = sqrt(dot(c, c));
    return V{c.y / length, -c.x / length};
  };
  V v, unused;
  const V nA = normalAt(a, ea, 2, v), nB = normalAt(b, eb, 2 + na, unused);
  const V m = nA + nB;
  const J g = dot(x - v, inverse(sqrt(dot(m, m))) * m);
  const int n = 2 + na + nb;
  VertexBlendGap out;
  out.gap = g.v;
  out.weight = 0.5;
  out.gradient = g.g.head(n);
  out.hessian = g.h.topLeftCorner(n, n);
  return out;
}

double pairedGap(const Eigen::Vector2d& xs, const std::vector<Segment>& masters, const MasterProjection& mp,
                 const ProjectionOptions& options) {
  if (!mp.paired()) return mp.projection.gap;
  Projection partner;
  const int b = vertexPartner(xs, masters, mp.segment, mp.projection, options, partner);
  if (b < 0) return mp.projection.gap;
  const double w = vertexBlendWeight(mp.projection.xi, partner.xi);
  return w * mp.projection.gap + (1 - w) * partner.gap;
}

}  // namespace aster::contact
