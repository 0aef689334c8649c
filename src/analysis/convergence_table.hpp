// STAT_NON_LINE's convergence table (INFO >= 1): a header per step, a row per Newton
// iteration (residuals, the matrix factorized, its time, and the contact status when the
// problem has contact terms). An observer of the Newton driver.
#pragma once
#include "analysis/newton_observer.hpp"

namespace aster::analysis {

class ConvergenceTable : public NewtonObserver {
 public:
  // contactColumn: the problem has contact terms, whose status each row ends with.
  explicit ConvergenceTable(bool contactColumn) : contactColumn_(contactColumn) {}
  void stepStarted(double t0, double t1) override;
  void iterationDone(const NewtonIteration& iteration) override;

 private:
  bool contactColumn_;
};

}  // namespace aster::analysis
