// STAT_NON_LINE's convergence table (INFO >= 1): a header per step, a row per Newton
// iteration (residuals, with RECH_LINEAIRE the line search's trials and coefficient rho as
// code_aster's RECH. LINE. columns, the matrix factorized, its time, and the contact status
// when the problem has contact terms). An observer of the Newton driver.
#pragma once
#include "analysis/newton_observer.hpp"

namespace aster::analysis {

class ConvergenceTable : public NewtonObserver {
 public:
  // contactColumn: the problem has contact terms, whose status each row ends with;
  // lineSearchColumns: the driver searches along its corrections (RECH_LINEAIRE).
  explicit ConvergenceTable(bool contactColumn, bool lineSearchColumns = false)
      : contactColumn_(contactColumn), lineSearchColumns_(lineSearchColumns) {}
  void stepStarted(double t0, double t1) override;
  void iterationDone(const NewtonIteration& iteration) override;

 private:
  bool contactColumn_;
  bool lineSearchColumns_;
};

}  // namespace aster::analysis
