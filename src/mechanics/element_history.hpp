// The state of one element at the last accepted (converged) step, which a
// behaviour law with history integrates from (see behaviour_law.hpp). A null
// displacement or stress stands for zero; the variables must be given when the
// law has any.
#pragma once

namespace aster::mechanics {

struct ElementHistory {
  const double* displacement = nullptr;  // u_n, node-major like u
  const double* stress = nullptr;        // 4 per Gauss point (SIXX, SIYY, SIZZ, SIXY)
  const double* variables = nullptr;     // the law's internalVariableCount() per Gauss point
};

}  // namespace aster::mechanics
