#include "core/number_format.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace aster::format {

std::string shortest(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buffer[40];
  int digits = 1;
  for (; digits < 17; ++digits) {
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, v);
    if (std::strtod(buffer, nullptr) == v) break;
  }
  // Plain notation for integers up to 1e16 ("1000", not "1e+03"): %g keeps it while
  // the precision covers the exponent.
  const double magnitude = std::abs(v);
  if (magnitude >= 1 && magnitude < 1e16)
    digits = std::max(digits, static_cast<int>(std::floor(std::log10(magnitude))) + 1);
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, v);
  return buffer;
}

std::string significant(double v, int digits) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, v);
  return buffer;
}

std::string asterValue(double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.12G", v);
  return buffer;
}

std::string scientific(double v, int digits) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*E", digits, v);
  return buffer;
}

std::string scientificAligned(double v, int digits) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "% .*E", digits, v);
  return buffer;
}

}  // namespace aster::format
