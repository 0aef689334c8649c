#include "analysis/convergence_table.hpp"

#include <cstdio>

#include "core/messages.hpp"
#include "core/number_format.hpp"

namespace aster::analysis {

using format::scientific;

void ConvergenceTable::stepStarted(double /*t0*/, double t1) {
  Messages::info("  Instant " + scientific(t1, 6) +
                 "\n    iter  RESI_GLOB_RELA   RESI_GLOB_MAXI   matrix      time (s)   " +
                 (contactColumn_ ? "contact" : ""));
}

void ConvergenceTable::iterationDone(const NewtonIteration& it) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "    %4d  %s     %s         %-9s   %.2E   ", it.index, scientific(it.rela, 6).c_str(),
                scientific(it.maxi, 2).c_str(), it.matrix, it.seconds);
  Messages::info(buf + it.contact);
}

}  // namespace aster::analysis
