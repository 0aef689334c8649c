// Frictionless contact as terms added to the mechanical system (DEFI_CONTACT):
// DISCRETE (node-to-segment, a Lagrange multiplier per slave node, active set),
// CONTINUE (LAGS_C at the slave vertex nodes, augmented Lagrangian solved
// by the generalized Newton method), each also penalised, and LAC (mortar:
// nodal weighted gaps, semi-smooth Newton; mortar_contact.cpp). Kernels and
// conventions: src/contact.
//
// Pairing: every Newton iteration pairs the slave nodes (DISCRETE) or the
// slave cells' points (CONTINUE) with the master in the current configuration
// (update()), and the gap is linearized exactly, projection included: the
// geometric loop is part of Newton's (code_aster's ALGO_RESO_GEOM='NEWTON').
// At a master kink the nearest cell of a point can alternate between the two
// cells of the vertex from one iteration to the next: such a point is held
// (DISCRETE: by both cells' conditions; CONTINUE: at the vertex,
// contact/vertex_blend.hpp); a CONTINUE point that projects inside both has
// its gap blended.
//
// CONT_NOEU (outputFields), on every slave node (nodes of the slave cells):
//   CONT  1 in contact, 0 not (DISCRETE: the active set; CONTINUE: the
//         criterion of the integration points evaluated at the node);
//   JEU   the gap of the node against the master, > 0 open (0 when unpaired;
//         CONTINUE: blended where it projects inside two cells of a vertex);
//   RN    the normal pressure, <= 0 in compression, per unit reference length:
//         DISCRETE, the nodal multiplier (the sum of both when the node is
//         held in a groove) over the node's share of the slave length
//         A_i = int N_i dGamma_0; CONTINUE, LAGS_C at the node (the
//         middle node of a SEG3 with linear LAGS_C: the mean of its ends);
//   RNX, RNY  the nodal force the contact terms apply to the node (minus their
//         part of the residual at its DX, DY): > 0 along the master normal
//         when the master pushes the slave away.
// Scale: every zone has a stiffness scale S, the largest Young's modulus of the
// 2D cells touching its slave or master nodes (1 when none has one). The
// multipliers are stored in U divided by S, and their equations multiplied by S
// (DISCRETE: S g, or lambda itself at a node out of contact, whose diagonal is
// then S; CONTINUE: S int L_v g, ...), so that their rows and columns are of
// the order of the stiffness's and the residual's rows of forces. Then
// multiplying E, the loads and COEF_CONT by s multiplies the multipliers by s
// and leaves the Newton iterates, the statuses, the relative residuals and the
// pivots' lost digits as they were: without it, with E in Pa the separated
// points' block -int L L / COEF_CONT stood next to a Schur complement ~1e-13
// and the pivot test saw a singular matrix. With E = 1 (S = 1) the numbers are
// the same to the last bit. The coefficients (COEF_CONT, E_N, COEF_PENA_CONT)
// are absolute, as code_aster's: pressures per unit gap, not scaled.
//
// statusText(): active nodes (DISCRETE), points and nodes in contact (CONTINUE),
// and a contact residual in length units that vanishes at convergence:
//   DISCRETE  max over slave nodes of |g| (active; |g - RN/E_N| penalised)
//             and of the penetration max(0, -g) (inactive);
//   CONTINUE  max over LAGS_C nodes v of |R_v| / A_v, R_v the residual of the
//             node's LAGS_C equation (int L_v g at points in contact, minus
//             int L_v lambda/COEF_CONT elsewhere) and A_v = int L_v dGamma_0:
//             a gap averaged around the node.
#pragma once
#include <memory>
#include <utility>
#include <vector>

#include "contact/continue_formulation.hpp"
#include "analysis/additional_terms.hpp"
#include "analysis/mechanical_system.hpp"

namespace aster::analysis {

// What DEFI_CONTACT sets per ZONE.
struct ZoneSettings {
  // ALGO_CONT='PENALISATION' when > 0: DISCRETE, E_N (pressure per unit
  // penetration: a node carries E_N * g times its share of the slave length);
  // CONTINUE, COEF_PENA_CONT (lambda = COEF_PENA_CONT * g where g < 0).
  double penalty = 0;
  double rho = 100.0;  // COEF_CONT (CONTINUE, ALGO_CONT='STANDARD'), a pressure per unit gap
  contact::ContactIntegration integration = contact::ContactIntegration::Gauss;  // CONTINUE: INTEGRATION
  int gaussPoints = 3;                                                            // ORDRE_INT
  // LAGS_C at every node of a slave cell, quadratic along a SEG3 (code_aster's:
  // INTERPOL_LAGS_C='QUADRATIQUE', the default), or at the vertex nodes only,
  // linear along the cell (INTERPOL_LAGS_C='LINEAIRE').
  contact::MultiplierInterpolation multipliers = contact::MultiplierInterpolation::Quadratic;
  // CONTINUE, CONTACT_INIT: the statuses of the first Newton iteration of the
  // computation (None: the criterion, i.e. 'INTERPENETRE'; Contact: 'OUI'; Separated: 'NON').
  contact::ForcedStatus initialStatus = contact::ForcedStatus::None;
  // LAC, ESPACE_LAGS_C='PAIRE': one polynomial multiplier over each pair of
  // neighbouring slave cells (mortar_contact.cpp), instead of one per node.
  bool lacPairs = false;
  // LAC: the coefficient c of the status criterion LAGS_C + c x gap <= 0 (a
  // pressure per unit gap; DEFI_CONT's COEF_CONT); <= 0: S / D_j (mortar_contact.cpp).
  double statusCoefficient = 0;
  double outsideTolerance = 0.5;  // TOLE_PROJ_EXT, in master xi units
  double maxDistance = -1;        // DIST_APPA (< 0: no limit)
  std::vector<int> excludedNodes;  // SANS_GROUP_NO, SANS_GROUP_MA: slave nodes without contact
};

struct ContactZone {
  std::vector<int> masterCells;  // mesh cells (SEG2/SEG3), oriented: the master normal points to the slave
  std::vector<int> slaveCells;
  ZoneSettings settings;
};

struct ContactSettings {
  bool continueFormulation = false;  // FORMULATION='CONTINUE', else 'DISCRETE'
  // ALGO_CONT='LAC' (CONTINUE, every zone): mortar contact (mortar_contact.cpp).
  bool mortar = false;
  // LISSAGE='OUI' (CONTINUE only): the gap (JEU of CONT_NOEU too) and the
  // contact force use the smoothed master normals of contact/smoothed_normal.hpp
  // (master nodes in at most two master cells); the tangent is not symmetric.
  bool smoothNormals = false;
  int info = 1;                      // INFO=2: the contact state of each converged instant is printed
};

// The first cell of `cells` (segments) whose normal (dy, -dx) points into the
// 2D cell of `mesh` it bounds (VERI_NORM), with that cell; -1 when none does.
// Segments bounding no 2D cell (a rigid master) or two of them are not checked.
std::pair<int, int> inwardContactCell(const mesh::Mesh& mesh, const std::vector<int>& cells);

std::unique_ptr<AdditionalTerms> makeContactTerms(const MechanicalSystem& system, std::vector<ContactZone> zones,
                                                  const ContactSettings& settings);

}  // namespace aster::analysis
