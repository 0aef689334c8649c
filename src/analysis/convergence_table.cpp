#include "analysis/convergence_table.hpp"

#include <cstdio>

#include "core/messages.hpp"

namespace aster::analysis {
namespace {

std::string sci(double v, int digits = 6) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*E", digits, v);
  return buf;
}

}  // namespace

void ConvergenceTable::stepStarted(double /*t0*/, double t1) {
  Messages::info("  Instant " + sci(t1) + "\n    iter  RESI_GLOB_RELA   RESI_GLOB_MAXI   matrix      time (s)   " +
                 (contactColumn_ ? "contact" : ""));
}

void ConvergenceTable::iterationDone(const NewtonIteration& it) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "    %4d  %s     %s         %-9s   %.2E   ", it.index, sci(it.rela).c_str(),
                sci(it.maxi, 2).c_str(), it.matrix, it.seconds);
  Messages::info(buf + it.contact);
}

}  // namespace aster::analysis
