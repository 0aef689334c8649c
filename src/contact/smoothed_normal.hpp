// Smoothed master normals (DEFI_CONTACT LISSAGE='OUI'), 2D, and the gap they
// give with its exact first and second variations.
//
// Normal at a master node: the normalised mean of the unit normals, at that
// node, of the master cells around it (code_aster's definition):
//   n_a = s_a / |s_a|,  s_a = sum over cells e around node a of nu_e(xi_a^e),
//   nu_e(xi) = (t_y, -t_x) / |t|, t = dx_e/dxi (segment.hpp's normal),
// with xi_a^e where node a sits on e (-1, +1, or 0 for a SEG3's middle node).
// Normal at xi on a master segment: the interpolation of its nodes' normals,
// normalised:  n~(xi) = m / |m|,  m = sum_a N_a(xi) n_a.
// The projection of a slave point stays the closest point xi* of the segment
// (projection.hpp); only the normal of the gap changes:
//   g = (x_s - x_m(xi*)) . n~(xi*).
// On a mesh of a smooth curve the nodal normal is the curve's to O(h^2) on a
// smoothly graded SEG2 mesh (the facet normal: O(h)), and n~ is continuous
// from one segment to the next.
//
// The contact force acts along n~, as in code_aster: its virtual work is
// (lambda + rho g) dg~ with dg~ = n~ . (dx_s - sum_a N_a(xi*) dy_a), n~ and
// xi* held, while the gap equations use g itself. (The exact variation of g
// is along the cell's own normal at a point lying on the cell: a slave point
// on a master vertex would be pushed along one cell's normal or the other's
// from one iteration to the next.) The contact tangent is the exact
// derivative of these terms, hence not symmetric.
// g depends on x_s, the segment's nodes and, through the n_a, on the nodes of
// the cells around the segment's nodes: the segment's PATCH. g, its first and
// second derivatives, and the force direction with its first derivatives are
// exact (forward second-order dual numbers on z = (x_s, patch nodes, xi),
// then xi*(q) eliminated as in gap.hpp).
#pragma once
#include <array>
#include <vector>

#include <Eigen/Core>

#include "contact/projection.hpp"
#include "contact/segment.hpp"

namespace aster::contact {

// The nodes a segment's smoothed normal depends on.
struct NormalPatch {
  // A master cell touching one of the segment's nodes.
  struct Facet {
    fem::CellType type = fem::CellType::SEG2;
    std::array<int, 3> node{{0, 0, 0}};  // its nodes, as indices into `nodes`
    double xi = 0;                      // where the segment's node sits on it
  };
  // Current coordinates: the segment's own nodes first, in its node order,
  // then the other nodes of the facets.
  std::vector<Eigen::Vector2d> nodes;
  std::array<std::vector<Facet>, 3> facets;  // per node of the segment (the segment itself included)
};

// Two cells around each node of a SEG3 (a master line) touch 7 nodes at most.
inline constexpr int kMaxPatchNodes = 7;

// n_a of node a (0, 1, 2) of the segment whose patch is given.
Eigen::Vector2d smoothedNodeNormal(const NormalPatch& patch, int a);
// n~(xi) on `segment` (its nodes are the patch's first ones).
Eigen::Vector2d smoothedNormal(const Segment& segment, const NormalPatch& patch, double xi);

struct SmoothedGap {
  double gap = 0;
  Eigen::VectorXd gradient;  // dg/dq, q = (x_s, patch nodes): size 2 + 2 * patch nodes
  Eigen::MatrixXd hessian;   // d2g/dq2, symmetric
  // The direction of the contact force, the variation of the gap with n~ and
  // the projection held: dg~ = n~ . (dx_s - sum_a N_a(xi*) dy_a) (code_aster's),
  // and its derivative d(force)/dq (xi*(q) and n~(q) varying).
  Eigen::VectorXd force;
  Eigen::MatrixXd forceJacobian;
};

// g at a given (Inside or Clamped) projection of xs on `segment`, with its
// derivatives (a Clamped projection holds xi at the end). Throws for an
// Outside or degenerate projection, as linearizeGap.
SmoothedGap linearizeSmoothedGap(const Eigen::Vector2d& xs, const Segment& segment, const NormalPatch& patch,
                                 const Projection& projection);
// g alone.
double smoothedGap(const Eigen::Vector2d& xs, const Segment& segment, const NormalPatch& patch, double xi);

}  // namespace aster::contact
