#include "expr/function.hpp"

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
