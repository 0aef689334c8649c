// DISCRETE node-to-segment terms and the active-set update (see discrete.hpp).
#include "contact/discrete.hpp"

#include <cmath>
#include <string>

namespace aster::contact {

DiscreteNodeTerms discreteNodeTerms(const NodeGap& gap, double lambda, bool active, double penalty) {
  if (penalty < 0 || !std::isfinite(penalty))
    throw Error("DISCRETE contact: the penalty stiffness must be >= 0, got " + std::to_string(penalty));
  const int n = static_cast<int>(gap.gradient.size());
  DiscreteNodeTerms t;
  t.residualU.setZero(n);
  t.tangentUU.setZero(n, n);
  t.tangentULambda.setZero(n);
  if (active) {
    t.residualU = lambda * gap.gradient;
    t.residualLambda = gap.gap;
    t.tangentUU = lambda * gap.hessian;
    t.tangentULambda = gap.gradient;
    t.tangentLambdaLambda = 0;
    if (penalty > 0) {
      t.residualLambda -= lambda / penalty;
      t.tangentLambdaLambda = -1 / penalty;
    }
  } else {
    t.residualLambda = lambda;
    t.tangentLambdaLambda = 1;
  }
  return t;
}

ActiveSetChange updateActiveSet(const std::vector<double>& gaps, const std::vector<double>& multipliers,
                                std::vector<bool>& active, const ActiveSetOptions& options) {
  if (gaps.size() != active.size() || multipliers.size() != active.size())
    throw Error("contact active set: expected as many gaps, multipliers and flags, got " + std::to_string(gaps.size()) +
                ", " + std::to_string(multipliers.size()) + " and " + std::to_string(active.size()));
  ActiveSetChange change;
  for (std::size_t i = 0; i < active.size(); ++i)
    if (!active[i] && gaps[i] < -options.gapTolerance) {
      active[i] = true;
      ++change.activated;
    }
  if (change.activated > 0) return change;
  int worst = -1;
  for (std::size_t i = 0; i < active.size(); ++i) {
    if (!active[i] || !(multipliers[i] > options.multiplierTolerance)) continue;
    if (options.releaseAllAtOnce) {
      active[i] = false;
      ++change.released;
    } else if (worst < 0 || multipliers[i] > multipliers[worst]) {
      worst = static_cast<int>(i);
    }
  }
  if (worst >= 0) {
    active[worst] = false;
    change.released = 1;
  }
  return change;
}

}  // namespace aster::contact
