// RECH_LINEAIRE: the line search on a Newton direction dU. The step U + rho dU is chosen
// so that the residual projected on the direction, f(rho) = dU . R(U + rho dU) (R the
// out-of-balance forces of the free unknowns), nearly vanishes: |f(rho)| <= RESI_LINE_RELA
// |f(0)|, as code_aster's functional (R5.03.01). f(0) = -dU . K dU < 0 for a descent
// direction; f(1) ~ 0 when the full Newton step is right.
//
// CORDE: secant steps through the last two trials, starting from (0, f(0)) and rho = 1.
// MIXTE: a bracketing search: rho is multiplied by 3 until f changes sign, then the
// secant of the last two trials within the bracket, or its middle when the last trial
// did not reduce |f| (or the secant leaves the bracket).
// Every trial rho is kept in [RHO_MIN, RHO_MAX] and out of ]-RHO_EXCL, RHO_EXCL[. After
// ITER_LINE_MAXI secant steps (ITER_LINE_MAXI + 1 trials) the trial of smallest |f| is taken.
#pragma once
#include <functional>

namespace aster::analysis {

struct LineSearchSettings {
  enum class Method { Corde, Mixte };
  Method method = Method::Corde;
  double resiLineRela = 1e-1;  // RESI_LINE_RELA
  int iterLineMaxi = 3;        // ITER_LINE_MAXI
  double rhoMin = 1e-2;        // RHO_MIN
  double rhoMax = 1e1;         // RHO_MAX
  double rhoExcl = 0.9e-2;     // RHO_EXCL
};

struct LineSearchOutcome {
  double rho = 1;          // the coefficient chosen
  double f = 0;            // f(rho)
  int trials = 0;          // evaluations of f (f(0) not counted)
  bool converged = false;  // |f(rho)| <= RESI_LINE_RELA |f(0)|
  bool failedTrial = false;  // a trial could not be evaluated (the search stopped there)
};

// f(rho) for a trial; returns false when the state at rho cannot be evaluated (an
// inverted cell), which stops the search with the best rho found so far (1 if none).
using LineFunctional = std::function<bool(double rho, double& f)>;

// The search from f0 = f(0).
LineSearchOutcome lineSearch(const LineSearchSettings& settings, double f0, const LineFunctional& f);

// rho brought into [rhoMin, rhoMax] and out of ]-rhoExcl, rhoExcl[.
double admissibleRho(const LineSearchSettings& settings, double rho);

}  // namespace aster::analysis
