// The gap of a slave point that projects INSIDE two master segments sharing a
// node (a master vertex where the surface has a kink), with its exact first
// and second variations, 2D.
//
// Near a kink the closest-point gap g = min(g_A, g_B) over the two segments
// (above a groove; max below a ridge) is continuous but its variation, the
// direction of the contact force, jumps from one segment's normal to the
// other's across the bisector. A point whose equilibrium lies there (a slave
// point right above the vertex of a symmetric groove) is pushed along one
// normal, then the other, from one Newton iteration to the next: Newton's
// method cycles. In that double-projection region the gap is therefore the
// blend
//   g = w g_A + (1 - w) g_B,   w = S(phi_A / (phi_A + phi_B)),
//   phi = 1 - xi*^2 (0 when the projection reaches either end of its segment),
//   S(s) = s^2 (3 - 2 s) (S(0) = 0, S(1) = 1, S'(0) = S'(1) = 0),
// with g_A, g_B, xi*_A, xi*_B each segment's own gap and projection (gap.hpp).
// Where one projection reaches an end of its segment the region ends, phi of
// that segment vanishes and g is the other segment's gap with the same
// value and variation: the gap is C1 across the region's boundary, smooth
// inside, symmetric in A and B, and its variation on the bisector of a
// symmetric kink is the mean of the two normals (a force along the
// bisector). On that bisector g_A = g_B, so the blend is the distance there;
// elsewhere in the region it lies between g_A and g_B (the closest point
// takes the smaller one above a groove, the larger below a ridge).
// Away from double projections at a shared node nothing changes.
//
// Variables: q = (x_s, A's nodes, B's nodes), the shared node appearing in
// both blocks (the caller adds the two blocks' rows and columns of that node,
// which is the derivative with respect to the one node).
#pragma once
#include <vector>

#include <Eigen/Core>

#include "contact/gap.hpp"
#include "contact/projection.hpp"
#include "contact/segment.hpp"

namespace aster::contact {

// The segment (index in `masters`, other than `nearest`) that shares a node
// with masters[nearest] (the same coordinates) and on which xs projects
// Inside, as masters[nearest] does; the nearest such one. -1 when none; then
// the gap is masters[nearest]'s own. `partner` receives its projection.
int vertexPartner(const Eigen::Vector2d& xs, const std::vector<Segment>& masters, int nearest,
                  const Projection& nearestProjection, const ProjectionOptions& options, Projection& partner);

// w of the blend (A's weight) from the two projections' xi.
double vertexBlendWeight(double xiA, double xiB);

struct VertexBlendGap {
  double gap = 0;
  double weight = 0;          // w, the weight of A
  Eigen::VectorXd gradient;   // dg/dq, size 2 + 2 (A's nodes + B's nodes)
  Eigen::MatrixXd hessian;    // d2g/dq2, symmetric
};

// The blended gap from the two linearized gaps (both Inside projections).
VertexBlendGap blendVertexGaps(const NodeGap& a, const NodeGap& b);

// A point HELD at the vertex of two segments (the caller's choice: a point
// whose nearest segment alternates between them from one Newton iteration to
// the next, whatever the region it lies in): the gap to the line through the
// shared node v across the mean normal of the two segments there,
//   g = (x_s - v) . n_v,   n_v = (n_A(v) + n_B(v)) / |n_A(v) + n_B(v)|,
// each segment's normal at its end v (segment.hpp); q as above. Smooth in
// every variable: the force of a held point is along n_v, along the bisector
// of a symmetric kink, and the point may rest anywhere near the vertex. The
// two segments must share a node.
VertexBlendGap heldVertexGap(const Eigen::Vector2d& xs, const Segment& a, const Segment& b);
// The node of `a` (0 or 1) that `b` shares, and b's; false when none.
bool sharedVertex(const Segment& a, const Segment& b, int& nodeA, int& nodeB);

// The gap of xs paired with masters[mp.segment]: blended when it has a vertex partner.
double pairedGap(const Eigen::Vector2d& xs, const std::vector<Segment>& masters, const MasterProjection& mp,
                 const ProjectionOptions& options);

}  // namespace aster::contact
