// The state of one element at the last accepted (converged) step, which a
// behaviour law with history integrates from (see behaviour_law.hpp). A null
// displacement or stress stands for zero; the variables must be given when the
// law has any. The instant of the new state and its distance from the
// accepted one are for rate-dependent laws (LEMAITRE, NORTON): zero when the
// state evaluated is the accepted one.
#pragma once

namespace aster::mechanics {

struct ElementHistory {
  const double* displacement = nullptr;  // u_n, node-major like u
  const double* stress = nullptr;        // 4 per Gauss point (SIXX, SIYY, SIZZ, SIXY)
  const double* variables = nullptr;     // the law's internalVariableCount() per Gauss point
  double time = 0.0;                     // INST of the state evaluated
  double timeIncrement = 0.0;            // time minus the INST of the accepted state
};

}  // namespace aster::mechanics
