#include "contact/mortar.hpp"

#include <algorithm>
#include <cmath>

#include "fem/quadrature.hpp"

namespace aster::contact {
namespace {

using J = MortarJet;
using JV = JetVec2<kMortarDofs>;

// Shape functions of a SEG2 / SEG3 at a Jet xi (segment.hpp's conventions).
struct JetShape {
  J N[3], dN[3];
  double d2N[3] = {0, 0, 0};
};
JetShape jetShape(fem::CellType type, const J& xi) {
  JetShape s;
  if (type == fem::CellType::SEG3) {
    const J xi2 = xi * xi;
    s.N[0] = 0.5 * (xi2 - xi);
    s.N[1] = 0.5 * (xi2 + xi);
    s.N[2] = 1.0 - xi2;
    s.dN[0] = xi - 0.5;
    s.dN[1] = xi + 0.5;
    s.dN[2] = -2.0 * xi;
    s.d2N[0] = 1;
    s.d2N[1] = 1;
    s.d2N[2] = -2;
  } else {
    s.N[0] = 0.5 * (1.0 - xi);
    s.N[1] = 0.5 * (1.0 + xi);
    s.dN[0] = J::constant(-0.5);
    s.dN[1] = J::constant(0.5);
  }
  return s;
}

// sum_a c_a p_a for Jet coefficients and Jet points.
JV combine(const J* c, const JV* p, int n) {
  JV r{c[0] * p[0].x, c[0] * p[0].y};
  for (int a = 1; a < n; ++a) {
    r.x += c[a] * p[a].x;
    r.y += c[a] * p[a].y;
  }
  return r;
}

// a x b (the z component).
J cross(const JV& a, const JV& b) { return a.x * b.y - a.y * b.x; }

// Double-precision geometry of a segment at xi: point, dx/dxi, d2x/dxi2.
struct Point {
  Eigen::Vector2d x, t, d2;
};
Point at(fem::CellType type, const SegmentNodes& X, double xi) {
  const auto s = segmentShape(type, xi);
  const int n = type == fem::CellType::SEG3 ? 3 : 2;
  Point p;
  p.x = X.topRows(n).transpose() * s.N.head(n);
  p.t = X.topRows(n).transpose() * s.dN.head(n);
  p.d2 = X.topRows(n).transpose() * s.d2N.head(n);
  return p;
}

// The master parameter eta where the line through x along n (i.e. orthogonal
// to t) meets the master: (y(eta) - x) . t = 0, the root nearest the
// linearized one. False when the line misses the master's curve.
bool meetMaster(const Segment& m, const Eigen::Vector2d& x, const Eigen::Vector2d& t, double& eta) {
  if (m.type == fem::CellType::SEG3) {
    const Eigen::Vector2d y1 = m.x.row(0), y2 = m.x.row(1), y3 = m.x.row(2);
    const double A = 0.5 * (y1 + y2 - 2 * y3).dot(t), B = 0.5 * (y2 - y1).dot(t), C = (y3 - x).dot(t);
    const double disc = B * B - 4 * A * C;
    if (disc < 0) return false;
    const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
    if (q == 0) return false;
    eta = C / q;  // the root that tends to -C/B as the master straightens
  } else {
    const Eigen::Vector2d c = 0.5 * (m.x.row(0) + m.x.row(1)).transpose(),
                          d = 0.5 * (m.x.row(1) - m.x.row(0)).transpose();
    const double dt = d.dot(t);
    if (dt == 0) return false;
    eta = -(c - x).dot(t) / dt;
  }
  return std::isfinite(eta);
}

// s(xi) = (y - x(xi)) . t(xi): its sign tells on which side of the slave's
// normal line at xi the point y lies.
double side(const MortarSlave& s, const Eigen::Vector2d& y, double xi) {
  const Point p = at(s.type, s.current, xi);
  return (y - p.x).dot(p.t);
}

// The root in [-1, 1] of side(y, .), given that it changes sign there:
// Newton's method kept inside the bracket (bisection when it leaves it).
double sideRoot(const MortarSlave& s, const Eigen::Vector2d& y) {
  double a = -1, b = 1, fa = side(s, y, a);
  double xi = 0;
  {
    const Point pa = at(s.type, s.current, -1), pb = at(s.type, s.current, 1);
    const double sa = (y - pa.x).dot(pa.t), sb = (y - pb.x).dot(pb.t);
    xi = sa - sb != 0 ? -1 + 2 * sa / (sa - sb) : 0;  // the chord's estimate
  }
  for (int k = 0; k < 100; ++k) {
    const Point p = at(s.type, s.current, xi);
    const double f = (y - p.x).dot(p.t);
    if (f == 0) return xi;
    if ((f < 0) == (fa < 0)) {
      a = xi;
      fa = f;
    } else {
      b = xi;
    }
    const double df = -p.t.dot(p.t) + (y - p.x).dot(p.d2);
    double next = df != 0 ? xi - f / df : 0.5 * (a + b);
    if (!(next > a && next < b)) next = 0.5 * (a + b);
    if (std::fabs(next - xi) <= 1e-15 * (1 + std::fabs(xi)) || b - a <= 1e-15) return next;
    xi = next;
  }
  return xi;
}

// One end of the overlap: a slave end (fixed) or the root of side(y_b, .).
struct OverlapEnd {
  double xi = 0;
  int masterNode = -1;  // -1: a slave end
};

}  // namespace

std::array<double, 3> slaveShares(const MortarSlave& slave) {
  std::array<double, 3> out{0, 0, 0};
  const auto& q = fem::gaussLegendre(6);
  const int n = slave.nodes();
  for (int i = 0; i < q.size(); ++i) {
    const double xi = q.points[i](0);
    const auto sh = segmentShape(slave.type, xi);
    const double J0 = (slave.reference.topRows(n).transpose() * sh.dN.head(n)).norm();
    for (int a = 0; a < n; ++a) out[a] += q.weights[i] * J0 * sh.N(a);
  }
  return out;
}

namespace {

// The overlap, in doubles: the slave points whose normal line passes between
// the master's end nodes (side() of opposite signs), when the two face each
// other at its middle, close enough. False when there is none.
bool findOverlap(const MortarSlave& slave, const Segment& master, const MortarOptions& options, OverlapEnd& lo,
                 OverlapEnd& hi) {
  const Eigen::Vector2d ends[2] = {master.x.row(0).transpose(), master.x.row(1).transpose()};
  auto inside = [&](double xi) { return side(slave, ends[0], xi) * side(slave, ends[1], xi) <= 0; };
  OverlapEnd roots[2];
  int found = 0;
  for (int b = 0; b < 2; ++b)  // a root at a slave end is that end's inside()
    if (side(slave, ends[b], -1) * side(slave, ends[b], 1) < 0) roots[found++] = {sideRoot(slave, ends[b]), b};
  if (found == 2 && roots[1].xi < roots[0].xi) std::swap(roots[0], roots[1]);
  const bool in0 = inside(-1), in1 = inside(1);
  if (in0 && in1) {
    lo = {-1, -1};
    hi = {1, -1};
  } else if (in0) {
    if (found == 0) return false;
    lo = {-1, -1};
    hi = roots[0];
  } else if (in1) {
    if (found == 0) return false;
    lo = roots[found - 1];
    hi = {1, -1};
  } else {
    if (found < 2) return false;
    lo = roots[0];
    hi = roots[1];
  }
  if (!(hi.xi - lo.xi > 1e-12)) return false;
  const Point p = at(slave.type, slave.current, 0.5 * (lo.xi + hi.xi));
  double eta = 0;
  if (!meetMaster(master, p.x, p.t, eta)) return false;
  const auto f = segmentFrame(master, std::clamp(eta, -1.0, 1.0));
  const Eigen::Vector2d n(p.t(1), -p.t(0));
  if (!(n.dot(f.normal) < 0)) return false;
  const double gap = (f.point - p.x).dot(n) / n.norm();
  return options.maxDistance < 0 || std::fabs(gap) <= options.maxDistance;
}

}  // namespace

bool mortarPaired(const MortarSlave& slave, const Segment& master, const MortarOptions& options) {
  OverlapEnd lo, hi;
  return findOverlap(slave, master, options, lo, hi);
}

MortarPair mortarPair(const MortarSlave& slave, const Segment& master, const MortarOptions& options) {
  MortarPair out;
  const int ns = slave.nodes(), nm = master.nodes();
  out.slaveNodes = ns;
  out.masterNodes = nm;
  for (auto& G : out.weightedGap) G = J::constant(0);
  OverlapEnd lo, hi;
  if (!findOverlap(slave, master, options, lo, hi)) return out;
  out.paired = true;
  out.lo = lo.xi;
  out.hi = hi.xi;

  // 2. The same in Jet arithmetic, over q = [x_1 .. x_ns, y_1 .. y_nm].
  JV x[3], y[3];
  for (int a = 0; a < ns; ++a)
    x[a] = {J::variable(slave.current(a, 0), 2 * a), J::variable(slave.current(a, 1), 2 * a + 1)};
  for (int b = 0; b < nm; ++b)
    y[b] = {J::variable(master.x(b, 0), 2 * (ns + b)), J::variable(master.x(b, 1), 2 * (ns + b) + 1)};
  // An overlap end at a master node: the root of (y_b - x(xi)) . t(xi).
  auto endJet = [&](const OverlapEnd& e) {
    if (e.masterNode < 0) return J::constant(e.xi);
    const JV& yb = y[e.masterNode];
    return newtonRefine<kMortarDofs>(e.xi, [&](const J& xi, J& r, J& dr) {
      const JetShape s = jetShape(slave.type, xi);
      const JV p = combine(s.N, x, ns), t = combine(s.dN, x, ns);
      JV d2{J::constant(0), J::constant(0)};
      for (int a = 0; a < ns; ++a) d2 = d2 + JV{s.d2N[a] * x[a].x, s.d2N[a] * x[a].y};
      const JV gap = yb - p;
      r = dot(gap, t);
      dr = dot(gap, d2) - dot(t, t);
    });
  };
  const J xiLo = endJet(lo), xiHi = endJet(hi);
  const J half = 0.5 * (xiHi - xiLo);

  const auto& rule = fem::gaussLegendre(options.gaussPoints);
  for (int i = 0; i < rule.size(); ++i) {
    const double tg = rule.points[i](0);
    const J xi = xiLo + (1.0 + tg) * half;
    const JetShape s = jetShape(slave.type, xi);
    const JV p = combine(s.N, x, ns), t = combine(s.dN, x, ns);
    // The master point on the slave's normal line.
    double eta0 = 0;
    if (!meetMaster(master, Eigen::Vector2d(p.x.v, p.y.v), Eigen::Vector2d(t.x.v, t.y.v), eta0)) eta0 = 0;
    const J eta = newtonRefine<kMortarDofs>(eta0, [&](const J& e, J& r, J& dr) {
      const JetShape m = jetShape(master.type, e);
      r = dot(combine(m.N, y, nm) - p, t);
      dr = dot(combine(m.dN, y, nm), t);
    });
    const JetShape m = jetShape(master.type, eta);
    const JV ym = combine(m.N, y, nm);
    // g = (y - x) . (t_y, -t_x) / |t| = ((y - x) x t) / |t|.
    const J g = cross(ym - p, t) / sqrt(dot(t, t));
    // |dX/dxi| of the reference cell at xi.
    J Xx = J::constant(0), Xy = J::constant(0);
    for (int a = 0; a < ns; ++a) {
      Xx += slave.reference(a, 0) * s.dN[a];
      Xy += slave.reference(a, 1) * s.dN[a];
    }
    const J w = rule.weights[i] * half * sqrt(Xx * Xx + Xy * Xy);
    const J gw = g * w;
    for (int a = 0; a < ns; ++a) {
      out.weightedGap[a] += s.N[a] * gw;
      out.pairedShare[a] += s.N[a].v * w.v;
    }
  }
  return out;
}

}  // namespace aster::contact
