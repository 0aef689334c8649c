// What the Newton driver (StaticNonlinear) tells those who watch it: the convergence
// table (convergence_table.hpp) prints it; a test or a monitor may record it. The driver
// computes nothing for its observers that it would not compute anyway, except the
// contact status text of each iteration, asked of the contact terms only when someone
// watches.
#pragma once
#include <string>

namespace aster::analysis {

// One Newton iteration, told when it ends (after its correction, or when it is the last).
struct NewtonIteration {
  double time = 0;      // the instant the step goes to
  int index = 0;        // 0 for the step's first iteration
  double rela = 0;      // RESI_GLOB_RELA of the residual measured at its start
  double maxi = 0;      // RESI_GLOB_MAXI of that residual
  const char* matrix = "";  // "TANGENTE" or "ELASTIQUE" when a matrix was factorized, else ""
  double seconds = 0;   // its wall time
  std::string contact;  // how contact stood when the residual was measured ("" without contact terms)
  int lineSearchTrials = -1;  // RECH_LINEAIRE: residuals evaluated on its correction (-1: no line search)
  double rho = 1;             // the coefficient of its correction the line search chose
};

class NewtonObserver {
 public:
  virtual ~NewtonObserver() = default;
  // A step [t0, t1] starts (a whole one or a sub-step of a cut one).
  virtual void stepStarted(double /*t0*/, double /*t1*/) {}
  virtual void iterationDone(const NewtonIteration& /*iteration*/) {}
  // The step converged after `iterations` corrections, or was accepted unconverged
  // (CONVERGENCE/ARRET='NON': criteriaMet false).
  virtual void stepConverged(double /*t1*/, int /*iterations*/, bool /*criteriaMet*/) {}
  // The step failed (why) and is cut into `parts` sub-steps at cutting level `level` (1 first).
  virtual void stepCut(double /*t0*/, double /*t1*/, int /*parts*/, int /*level*/, const std::string& /*why*/) {}
};

}  // namespace aster::analysis
