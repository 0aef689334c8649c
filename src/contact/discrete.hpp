// DISCRETE node-to-segment contact (code_aster FORMULATION='DISCRETE',
// ALGO_CONT='CONTRAINTE'): one condition per slave node,
//   g(u) >= 0,   lambda <= 0,   lambda * g = 0,
// with g the gap of the slave node against its master segment (gap.hpp) and
// lambda the normal nodal force on the slave (<= 0 in compression): the force
// the master applies to the slave is -lambda * n_m.
// Lagrangian term added to the energy: lambda * g(u). Hence, in the global
// residual R = F_int - F_ext (+ these terms):
//   active node:   R_u += lambda * dg/dq,  R_lambda = g,
//                  K_uu += lambda * d2g/dq2, K_ulambda = K_lambdau^T = dg/dq;
//   inactive node: R_lambda = lambda (the equation lambda = 0), K_lambdalambda = 1.
// q = (slave x, y, master node 1 x, y, node 2 x, y[, node 3 x, y]).
//
// Penalisation (ALGO_CONT='PENALISATION'): an active node carries the force
// lambda = k g (k > 0 the node's penalty stiffness, k = E_N times the node's
// share of the slave length in aster-lite), i.e. the energy lambda g -
// lambda^2 / (2k), whose variation changes only the multiplier equation:
//   active node:   R_lambda = g - lambda / k,  K_lambdalambda = -1 / k
// (the rest as above). Nodes penetrate by g = lambda / k.
//
// Active set (updateActiveSet): every inactive node that penetrates
// (g < -gapTolerance) is activated; only when no node was activated, active
// nodes in tension (lambda > multiplierTolerance) are released: by default
// only the most tensile one per pass (one link at a time, as the active-set
// algorithm of code_aster's CONTRAINTE does, to avoid cycling), or all of them.
// The driver repeats solve + update until nothing changes.
#pragma once
#include <vector>

#include "contact/gap.hpp"

namespace aster::contact {

struct DiscreteNodeTerms {
  GapVector residualU;        // size 2 + 2 * master nodes
  double residualLambda = 0;
  GapMatrix tangentUU;        // d residualU / dq
  GapVector tangentULambda;   // d residualU / dlambda = (d residualLambda / dq)^T when active
  double tangentLambdaLambda = 0;
};

// Terms of one slave node with multiplier lambda, active or not; penalty > 0
// is the node's penalty stiffness k (0: the exact constraint g = 0).
DiscreteNodeTerms discreteNodeTerms(const NodeGap& gap, double lambda, bool active, double penalty = 0);

struct ActiveSetOptions {
  double gapTolerance = 0;         // g < -gapTolerance activates an inactive node
  double multiplierTolerance = 0;  // lambda > multiplierTolerance releases an active node
  bool releaseAllAtOnce = false;
};

struct ActiveSetChange {
  int activated = 0;
  int released = 0;
  bool changed() const { return activated + released > 0; }
};

// Updates `active` in place from the current gaps and multipliers (same sizes).
ActiveSetChange updateActiveSet(const std::vector<double>& gaps, const std::vector<double>& multipliers,
                                std::vector<bool>& active, const ActiveSetOptions& options = {});

}  // namespace aster::contact
