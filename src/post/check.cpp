#include "post/check.hpp"

#include <cmath>
#include <cstdio>

#include "core/number_format.hpp"

namespace aster::post {
namespace {

CheckLine compare(double computed, double expected, double tolerance, bool relative, double scale,
                  const std::string& reference) {
  CheckLine line;
  line.reference = reference;
  line.expected = expected;
  line.computed = computed;
  line.relative = relative;
  line.tolerance = tolerance;
  const double diff = std::fabs(computed - expected);
  if (relative) {
    // A relative error is meaningless at zero: use ORDRE_GRANDEUR (or 1) as the scale.
    const double base = std::fabs(expected) > 0 ? std::fabs(expected) : (scale > 0 ? scale : 1.0);
    line.error = 100.0 * diff / base;
    line.tolerance = 100.0 * tolerance;
    line.ok = std::isfinite(computed) && diff <= tolerance * base;
  } else {
    line.error = diff;
    line.ok = std::isfinite(computed) && diff <= tolerance;
  }
  return line;
}

// A left-aligned column of 17 characters, always followed by a space.
std::string column(const std::string& s) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%-17s", s.c_str());
  std::string out = buf;
  if (out.back() != ' ') out += ' ';
  return out;
}

}  // namespace

std::vector<CheckLine> check(double computed, const CheckSpec& spec) {
  std::vector<CheckLine> lines;
  if (spec.hasValeCalc)
    lines.push_back(compare(computed, spec.valeCalc, spec.toleMachine, true, spec.ordreGrandeur, "NON_REGRESSION"));
  if (spec.reference != "NON_REGRESSION" && spec.hasValeRefe)
    lines.push_back(compare(computed, spec.valeRefe, spec.precision, spec.relative, spec.ordreGrandeur,
                            spec.reference));
  return lines;
}

std::string formatCheck(const std::vector<std::pair<std::string, std::string>>& what,
                        const std::vector<CheckLine>& lines, const std::string& legende) {
  std::string head = " ---- ", vals = "      ";
  for (const auto& [name, value] : what) {
    head += column(name);
    vals += column(value);
  }
  std::string out = head + "\n" + vals + "\n      " + column("REFERENCE") + column("LEGENDE") + column("VALE_REFE") +
                    column("VALE_CALC") + column("ERREUR") + "TOLE\n";
  for (const auto& l : lines) {
    const std::string percent = l.relative ? "%" : "";
    out += std::string(l.ok ? " OK   " : " NOOK ") + column(l.reference) + column(legende) +
           column(format::asterValue(l.expected)) + column(format::asterValue(l.computed)) +
           column(format::scientific(l.error, 3) + percent) + format::scientific(l.tolerance, 3) + percent + "\n";
  }
  return out;
}

}  // namespace aster::post
