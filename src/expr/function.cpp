#include "expr/function.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/error.hpp"

namespace aster::expr {

Function::~Function() = default;

double Function::operator()(std::initializer_list<double> args) const {
  const auto& names = parameters();
  if (args.size() != names.size()) {
    throw Error("function of (" + joinNames(names) + ") takes " + std::to_string(names.size()) +
                " argument(s), got " + std::to_string(args.size()));
  }
  return evaluate(args.begin());
}

int Function::parameterIndex(const std::string& name) const {
  const auto& names = parameters();
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return static_cast<int>(i);
  }
  return -1;
}

std::string numberText(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[40];
  int digits = 1;
  for (; digits < 17; ++digits) {
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
    if (std::strtod(buffer, nullptr) == value) break;
  }
  // Plain notation for integers up to 1e16 ("1000", not "1e+03"): %g keeps it while
  // the precision covers the exponent.
  const double magnitude = std::abs(value);
  if (magnitude >= 1 && magnitude < 1e16)
    digits = std::max(digits, static_cast<int>(std::floor(std::log10(magnitude))) + 1);
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  return buffer;
}

std::string joinNames(const std::vector<std::string>& names) {
  if (names.empty()) return "none";
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i) out += ", ";
    out += names[i];
  }
  return out;
}

}  // namespace aster::expr
