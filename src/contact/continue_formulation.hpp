// CONTINUE (mortar-like, Gauss-point) frictionless contact, code_aster
// FORMULATION='CONTINUE', ALGO_RESO_CONT='NEWTON', ALGO_RESO_GEOM='NEWTON':
// augmented Lagrangian solved by a generalized (semi-smooth) Newton method,
// with the pairing re-done at every call (geometric Newton).
//
// Unknowns of one slave cell (SEG2 or SEG3): its node displacements, the
// master nodes' displacements, and LAGS_C at m = multiplierCount() slave
// nodes. At a slave point xi, lambda = sum_v L_v(xi) LAGS_C_v is the normal
// traction on the slave per unit REFERENCE length (<= 0 in compression, 0 when
// separated; at convergence lambda = (Pi.N).n), and g the gap of x_s(xi)
// against the master (projection.hpp, gap.hpp; g > 0 separated). The same L_v
// interpolate the multiplier and its variation dlambda (test function):
//   Quadratic on a SEG3 slave, m = 3 (code_aster's: its 2D slave contact
//     elements carry LAGS_C on all three nodes): LAGS_C at nodes 1, 2 and the
//     middle node 3, L = the SEG3 shape functions (xi(xi-1)/2, xi(xi+1)/2, 1-xi^2);
//   Linear (any slave; also a SEG2 in Quadratic mode), m = 2: LAGS_C at the
//     two VERTEX nodes 1, 2 (a SEG3's middle node carries none),
//     L = ((1-xi)/2, (1+xi)/2).
// Contact terms are integrated on the slave in the REFERENCE configuration,
// dGamma_0 = |dX/dxi| dxi, by Gauss points (or at the nodes).
// Quadrature degree (straight reference cell: |dX/dxi| constant; n Gauss
// points are exact to degree 2n-1, Newton-Cotes at the nodes to degree 1 on a
// SEG2 (trapezoid) and 3 on a SEG3 (Simpson)): the multiplier block
// -(1/rho) int L_v L_w is of degree 2 (Linear) or 4 (Quadratic), hence exact
// with 2 Gauss points (Linear) or 3 (Quadratic, the default count). In
// Quadratic mode fewer than 3 Gauss points leave that 3x3 block singular (a
// sum of < 3 rank-one terms), so they are rejected; Nodes (Simpson) lumps it
// to a diagonal one (weights 1/3, 1/3, 4/3 times |dX/dxi|), not exact but
// regular. Terms with g or dg are not polynomial in general (curved master).
//
// Augmented multiplier lambda + rho g (rho = COEF_CONT). The energy-like
// function of the augmented Lagrangian, for lambda <= 0 and g >= 0, is
//   contact   (lambda + rho g <= 0): lambda g + rho g^2 / 2
//   separated (lambda + rho g > 0):  -lambda^2 / (2 rho)
// (continuous, C1 across the switch), whose variation gives the terms
//   contact:   (lambda + rho g) dg  +  g dlambda
//   separated: -(lambda / rho) dlambda
// i.e. W_c = int lambda dg dGamma_0 at the solution (lambda is the normal
// traction on the slave side), and g = 0 / lambda = 0 as the constraint
// equations. Note: the criterion is lambda + rho g < 0 (not lambda - rho g),
// the one consistent with lambda <= 0 in compression and g > 0 when separated:
// a penetrating point (g < 0) with lambda = 0 must switch to contact. A point
// touching with lambda = 0 (the start of a study whose slave lies on the
// master) counts as in contact, as code_aster's CONTACT_INIT='INTERPENETRE':
// otherwise a body held only by contact would be free at the first iteration;
// touching is to round-off (gapIsClosed: the criterion takes a gap within
// gapRoundOff as 0), since meshed surfaces touch only to their coordinates' digits.
// Penalisation (ALGO_CONT='PENALISATION', kappa = COEF_PENA_CONT): the
// pressure is lambda = kappa min(g, 0), written with the same LAGS_C unknowns
// through the energy-like function
//   contact   (g <= 0):  lambda g - lambda^2 / (2 kappa)
//   separated (g > 0):   -lambda^2 / (2 kappa)
// whose variation gives
//   contact:   lambda dg  +  (g - lambda / kappa) dlambda
//   separated: -(lambda / kappa) dlambda
// (the point penetrates by g = lambda / kappa; `augmented` holds kappa g).
// The tangent is the exact derivative of the residual for frozen statuses,
// including the projection and master curvature terms (gap.hpp), hence
// symmetric. A point whose projection falls outside every master segment is
// unpaired and treated as separated (its lambda is driven to 0).
// At a master kink (vertex_blend.hpp): a point that projects inside two
// segments sharing a node takes the blend of their gaps (without smoothed
// normals; with them its gap is continuous already), and a point HELD at
// their vertex (SlaveCell::held, LISSAGE or not) the gap across their mean
// normal there, its force along that gap's variation; g, dg and d2g are then
// over (x_s, one segment's nodes, the other's), the shared node in both
// blocks (the layout has it once per segment block).
//
// Residual and tangent are the contributions to ADD to the global residual
// R = F_int - F_ext and to its Jacobian. Cell DOF layout:
//   [slave node 1 x, y, node 2 x, y (, node 3 x, y)]
//   [master segment 0 nodes x, y ...][master segment 1 ...] ...
//   [LAGS_C node 1, LAGS_C node 2 (, LAGS_C node 3 in Quadratic mode on a SEG3)]
// (derivatives w.r.t. displacements = w.r.t. current coordinates).
// Smoothed master normals (LISSAGE='OUI', smoothed_normal.hpp): given a patch
// per master segment, the gap uses the smoothed normal n~, the force terms
// (lambda + rho g) dg and lambda dg take dg~ (along n~, n~ and the projection
// held) in place of dg, and the segment's block of the layout holds its
// patch's nodes (its own nodes first) instead of its nodes alone. The tangent
// is still the exact derivative of the residual, but not symmetric.
#pragma once
#include <array>
#include <vector>

#include <Eigen/Core>

#include "contact/projection.hpp"
#include "contact/segment.hpp"
#include "contact/smoothed_normal.hpp"

namespace aster::contact {

enum class ContactIntegration {
  Gauss,  // Gauss-Legendre with ContinueOptions::gaussPoints points
  Nodes,  // at the slave nodes: trapezoid (SEG2), Simpson (SEG3)
};

// Interpolation of LAGS_C (and of its variation) on the slave cell.
enum class MultiplierInterpolation {
  Linear,     // at the vertex nodes 1, 2 (SEG2 and SEG3 slaves)
  Quadratic,  // at nodes 1, 2, 3 with the SEG3 shape functions (a SEG2 slave stays Linear)
};

// Statuses imposed on the paired points instead of the criterion (CONTACT_INIT
// at the first iteration of a computation).
enum class ForcedStatus { None, Contact, Separated };

struct ContinueOptions {
  double rho = 100;  // COEF_CONT
  // ALGO_CONT='PENALISATION' when > 0: COEF_PENA_CONT (rho is then unused).
  double penalty = 0;
  ForcedStatus forcedStatus = ForcedStatus::None;
  ContactIntegration integration = ContactIntegration::Gauss;
  int gaussPoints = 3;  // >= 3 required with Quadratic multipliers on a SEG3
  MultiplierInterpolation multiplierInterpolation = MultiplierInterpolation::Linear;
  ProjectionOptions projection;
};

struct SlaveCell {
  fem::CellType type = fem::CellType::SEG2;
  SegmentNodes reference = SegmentNodes::Zero();  // node coordinates before deformation
  SegmentNodes current = SegmentNodes::Zero();    // reference + displacement
  // LAGS_C at slave nodes 1, 2, 3; entry 2 (node 3) is used only when
  // multiplierCount() == 3, and ignored otherwise.
  Eigen::Vector3d lagsC = Eigen::Vector3d::Zero();
  // Per integration point (in the rule's order; may be shorter or empty): the
  // two master segments (indices into the master list, -1: none) that HOLD it
  // at their shared vertex (vertex_blend.hpp, heldVertexGap), while its
  // projection on each is inside or clamped.
  std::vector<std::array<int, 2>> held;
};

// Number of LAGS_C unknowns of the cell (the last DOFs of its layout): 3 for a
// SEG3 slave with Quadratic multipliers, 2 otherwise.
int multiplierCount(const SlaveCell& slave, const ContinueOptions& options);

enum class PointStatus { Contact, Separated, Unpaired };
const char* pointStatusName(PointStatus s);

// What happened at one integration point (for output and diagnostics).
struct ContactPointState {
  double xi = 0;                       // on the slave cell
  double weight = 0;                   // quadrature weight * |dX/dxi|
  Eigen::Vector2d point = Eigen::Vector2d::Zero();  // current position
  PointStatus status = PointStatus::Separated;
  double gap = 0;                      // 0 when unpaired
  double pressure = 0;                 // interpolated LAGS_C (lambda)
  double augmented = 0;                // pressure + rho * gap, the criterion (penalisation: kappa * gap; a gap within round-off counts as 0)
  int masterSegment = -1;
  double masterXi = 0;
};

struct ContinueCellTerms {
  Eigen::VectorXd residual;
  Eigen::MatrixXd tangent;
  std::vector<ContactPointState> points;
  std::vector<int> masterOffsets;  // first DOF of each master segment
  int lagrangeOffset = 0;          // first LAGS_C DOF (multiplierCount of them, up to the end)
  int size() const { return static_cast<int>(residual.size()); }
};

// Residual, tangent and point data of one slave cell against the master
// segments (current coordinates). `out` is resized only when needed. With
// `patches` (one per master segment, whose first nodes are the segment's),
// the normals are smoothed.
void continueCellTerms(const SlaveCell& slave, const std::vector<Segment>& masters, const ContinueOptions& options,
                       ContinueCellTerms& out, const std::vector<NormalPatch>* patches = nullptr);

}  // namespace aster::contact
