#include "analysis/convergence_table.hpp"

#include <cstdio>

#include "core/messages.hpp"
#include "core/number_format.hpp"

namespace aster::analysis {

using format::scientific;

void ConvergenceTable::stepStarted(double /*t0*/, double t1) {
  Messages::info("  Instant " + scientific(t1, 6) +
                 "\n    iter  RESI_GLOB_RELA   RESI_GLOB_MAXI   " +
                 (lineSearchColumns_ ? "RL iter  RL rho       " : "") + "matrix      time (s)   " +
                 (contactColumn_ ? "contact" : ""));
}

void ConvergenceTable::iterationDone(const NewtonIteration& it) {
  // The line search columns are blank for an iteration without one (the prediction, the last).
  char search[32] = "";
  if (lineSearchColumns_ && it.lineSearchTrials >= 0)
    std::snprintf(search, sizeof search, "%7d  %s   ", it.lineSearchTrials, scientific(it.rho, 4).c_str());
  else if (lineSearchColumns_)
    std::snprintf(search, sizeof search, "%22s", "");
  char buf[128];
  std::snprintf(buf, sizeof buf, "    %4d  %s     %s         %s%-9s   %.2E   ", it.index, scientific(it.rela, 6).c_str(),
                scientific(it.maxi, 2).c_str(), search, it.matrix, it.seconds);
  Messages::info(buf + it.contact);
}

}  // namespace aster::analysis
