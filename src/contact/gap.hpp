// Normal gap of a slave point against one master segment (SEG2 or SEG3) and
// its exact first and second variations, 2D.
//
//   g(q) = (x_s - x_m(xi*)) . n_m(xi*),   x_m(xi) = sum_a N_a(xi) y_a,
//   n_m = (t_y, -t_x)/|t|, t = dx_m/dxi,
// with q = (x_s, y_1, y_2[, y_3]) the CURRENT coordinates, ordered
//   [x_s.x, x_s.y, y_1.x, y_1.y, y_2.x, y_2.y, (y_3.x, y_3.y)]
// (derivatives w.r.t. displacements are the same, x = X + u), and xi* the
// closest-point projection: r(q, xi) = (x_s - x_m(xi)) . dx_m/dxi = 0.
// Derivatives: with G(q, xi) = (x_s - x_m(xi)) . n_m(xi) and xi*(q) implicit,
//   dxi/dq   = -r_q / r_xi
//   d2xi/dq2 = -(r_qq + r_qxi dxi^T + dxi r_xiq + r_xixi dxi dxi^T) / r_xi
//   dg/dq    = G_q + G_xi dxi
//   d2g/dq2  = G_qq + G_qxi dxi^T + dxi G_xiq + G_xixi dxi dxi^T + G_xi d2xi
// (G_xi = 0 at the projection, kept for exactness), which carries the master
// curvature and the dependence of xi* on every DOF. For a CLAMPED projection
// (slave point past an end) xi is held at the end: dg/dq = G_q, d2g/dq2 = G_qq.
#pragma once
#include <Eigen/Core>

#include "contact/projection.hpp"
#include "contact/segment.hpp"

namespace aster::contact {

// Up to 8 DOFs (slave point + SEG3 master) without heap allocation.
inline constexpr int kMaxGapDofs = 8;
using GapVector = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxGapDofs, 1>;
using GapMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, kMaxGapDofs, kMaxGapDofs>;

struct NodeGap {
  Projection projection;
  double gap = 0;
  GapVector gradient;  // dg/dq, size 2 + 2 * master nodes
  GapMatrix hessian;   // d2g/dq2, symmetric
  GapVector xiGradient;  // dxi*/dq (zero when the projection is clamped)
  GapMatrix xiHessian;   // d2xi*/dq2 (zero when the projection is clamped)
};

// The round-off of a gap of xs against `master`: 1e-12 times the largest
// coordinate of xs and the master's nodes. Surfaces meshed to touch carry
// gaps of that size of either sign (coordinates computed as 0.1 k, written
// to 17 digits, a middle node at (a + b) / 2, ...): a gap within it is a
// point touching the master, which contact treats as closed (gapIsClosed).
double gapRoundOff(const Eigen::Vector2d& xs, const Segment& master);
inline bool gapIsClosed(double gap, const Eigen::Vector2d& xs, const Segment& master) {
  return gap <= gapRoundOff(xs, master);
}

// Gap of xs against `master` at a given (Inside or Clamped) projection, with
// its gradient and Hessian. Throws for an Outside projection, and when the
// projection is degenerate (r_xi >= 0: slave point at a centre of curvature).
NodeGap linearizeGap(const Eigen::Vector2d& xs, const Segment& master, const Projection& projection);

// Projects xs on master, then linearizes. Throws when xs falls outside it.
NodeGap nodeToSegmentGap(const Eigen::Vector2d& xs, const Segment& master, const ProjectionOptions& options = {});

}  // namespace aster::contact
