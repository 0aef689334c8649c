// DEFI_LIST_INST/ECHEC/SUBD_METHODE: how a failed step is cut.
// MANUEL: into SUBD_PAS equal sub-steps, at most SUBD_NIVEAU times in a row.
// AUTO (code_aster's extrapolation of the residuals, U4.34.03): the failed step's residuals,
// from the fourth iteration on, are fitted by iteration = a + b log(residual) (least
// squares, the last three points counted twice), which gives the iteration the criterion
// would have been reached at. Without enough iterations (fewer than 7 residuals) or a fit,
// the step is cut into 4 equal sub-steps. Otherwise into n sub-steps, a first one of a
// fraction r of the step and n - 1 equal ones: when the residual did not grow (b <= 0), or
// the fit reaches the criterion early (1.2 N < ITER_GLOB_MAXI, N the extrapolated
// iteration), n = 4 and r = 1/7 (r = 24 / ((3n + 1)^2 - 1)); otherwise (a residual that grew
// while below the criterion: the step failed for another reason) r = 0.48485
// exp((N - ITER_GLOB_MAXI) / b) and n the integer nearest to (sqrt(1 + 24 / r) - 1) / 3,
// n = 2 and r = 1/2 when that is below 2. No limit on the levels: a sub-step below
// SUBD_PAS_MINI stops the computation, with either method.
#pragma once
#include <vector>

namespace aster::analysis {

struct StepCut {
  int parts = 4;
  double firstFraction = 0.25;  // of the step, for the first sub-step; the others share the rest
  bool extrapolated = false;    // AUTO: from the residuals' extrapolation
};

// residuals: the failed step's, one per iteration from 0; criterion: RESI_GLOB_RELA (or
// MAXI) the residuals were measured against.
StepCut automaticCut(const std::vector<double>& residuals, double criterion, int iterGlobMaxi);

// The instants that end the sub-steps of [t0, t1] (the last is t1).
std::vector<double> subStepEnds(double t0, double t1, const StepCut& cut);

}  // namespace aster::analysis
