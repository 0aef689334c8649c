// Closest-point projection (see projection.hpp for the method).
#include "contact/projection.hpp"

#include <cmath>
#include <limits>
#include <string>

namespace aster::contact {

const char* projectionStatusName(ProjectionStatus s) {
  switch (s) {
    case ProjectionStatus::Inside: return "inside";
    case ProjectionStatus::Clamped: return "clamped";
    case ProjectionStatus::Outside: return "outside";
  }
  return "?";
}

namespace {

// The segment as a polynomial curve and the stationarity residual r(xi).
struct Curve {
  const Segment& s;
  const Eigen::Vector2d& xs;
  Eigen::Vector2d point(double xi) const { return s.x.transpose() * segmentShape(s.type, xi).N; }
  // r = (xs - x).x' and dr/dxi = -|x'|^2 + (xs - x).x''
  void residual(double xi, double& r, double& dr) const {
    const SegmentShape sh = segmentShape(s.type, xi);
    const Eigen::Vector2d x = s.x.transpose() * sh.N;
    const Eigen::Vector2d d1 = s.x.transpose() * sh.dN;
    const Eigen::Vector2d d2 = s.x.transpose() * sh.d2N;
    r = (xs - x).dot(d1);
    dr = -d1.squaredNorm() + (xs - x).dot(d2);
  }
  double r(double xi) const {
    double v, d;
    residual(xi, v, d);
    return v;
  }
};

// Root of r in [a, b] with r(a) > 0 >= r(b): Newton steps kept inside the
// shrinking bracket, bisection otherwise.
double safeguardedNewton(const Curve& c, double a, double b, int maxIterations) {
  double xi = 0.5 * (a + b);
  for (int it = 0; it < maxIterations; ++it) {
    double r, dr;
    c.residual(xi, r, dr);
    if (r == 0) return xi;
    if (r > 0) a = xi; else b = xi;
    double next = (dr != 0) ? xi - r / dr : 0.5 * (a + b);
    if (!(next > a && next < b)) next = 0.5 * (a + b);
    const double step = std::abs(next - xi);
    xi = next;
    if (step <= 1e-15 * (1 + std::abs(xi)) || (b - a) <= 1e-15) return xi;
  }
  return xi;
}

void fill(Projection& p, const Eigen::Vector2d& xs, const Segment& s, double xi) {
  p.xi = xi;
  p.master = segmentFrame(s, xi);
  const Eigen::Vector2d d = xs - p.master.point;
  p.gap = d.dot(p.master.normal);
  p.distance = d.norm();
}

}  // namespace

Projection projectOnSegment(const Eigen::Vector2d& xs, const Segment& master, const ProjectionOptions& options) {
  checkSegmentType(master.type, "master");
  if (!(options.outsideTolerance >= 0))
    throw Error("contact projection: outsideTolerance must be >= 0, got " + std::to_string(options.outsideTolerance));
  if (options.samples < 2) throw Error("contact projection: at least 2 sampling intervals are needed");
  const Curve c{master, xs};
  // Candidates: local minima inside, and the two ends.
  double bestXi = -1, bestD2 = (xs - c.point(-1)).squaredNorm();
  {
    const double d2 = (xs - c.point(1)).squaredNorm();
    if (d2 < bestD2) bestXi = 1, bestD2 = d2;
  }
  const int n = master.type == fem::CellType::SEG3 ? options.samples : 1;  // r is linear on a SEG2
  double xa = -1, ra = c.r(-1);
  for (int k = 1; k <= n; ++k) {
    const double xb = -1 + 2.0 * k / n, rb = c.r(xb);
    if (ra > 0 && rb <= 0) {
      const double xi = safeguardedNewton(c, xa, xb, options.maxIterations);
      const double d2 = (xs - c.point(xi)).squaredNorm();
      if (d2 < bestD2) bestXi = xi, bestD2 = d2;
    }
    xa = xb, ra = rb;
  }
  Projection p;
  fill(p, xs, master, bestXi);
  p.status = ProjectionStatus::Inside;
  if (std::abs(bestXi) == 1.0) {
    // At an end: is the slave point past it (r pushing outward)?
    const double r = c.r(bestXi);
    const double outward = bestXi > 0 ? r : -r;
    const double scale = p.master.jacobian * p.master.jacobian;
    p.beyond = std::max(0.0, outward) / scale;
    // Roundoff-level overshoot is a point at the end itself.
    if (p.beyond > 1e-12) p.status = p.beyond <= options.outsideTolerance ? ProjectionStatus::Clamped : ProjectionStatus::Outside;
    else p.beyond = 0;
  }
  return p;
}

MasterProjection projectOnMaster(const Eigen::Vector2d& xs, const std::vector<Segment>& masters,
                                 const ProjectionOptions& options) {
  if (masters.empty()) throw Error("contact projection: no master segment given");
  MasterProjection best, nearestOutside;
  double bestDist = std::numeric_limits<double>::infinity(), outsideDist = bestDist;
  for (int k = 0; k < static_cast<int>(masters.size()); ++k) {
    const Projection p = projectOnSegment(xs, masters[k], options);
    if (p.status == ProjectionStatus::Outside) {
      if (p.distance < outsideDist) outsideDist = p.distance, nearestOutside.projection = p;
      continue;
    }
    const double tie = 1e-12 * (1 + bestDist);
    const bool better = p.distance < bestDist - tie ||
                        (p.distance <= bestDist + tie && p.status == ProjectionStatus::Inside &&
                         best.projection.status != ProjectionStatus::Inside);
    if (best.segment < 0 || better) {
      best.segment = k;
      best.projection = p;
      bestDist = p.distance;
    }
  }
  // DIST_APPA: a point too far from the master is not paired.
  if (best.segment >= 0 && options.maxDistance >= 0 && best.projection.distance > options.maxDistance) {
    best.segment = -1;
    return best;
  }
  return best.segment >= 0 ? best : nearestOutside;
}

}  // namespace aster::contact
