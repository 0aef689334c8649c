#include "expr/constant.hpp"

namespace aster::expr {

bool takesOnly(const Function& f, const std::string& name) {
  const auto& p = f.parameters();
  return p.size() == 1 && (p[0] == name || p[0] == kAnyParameter);
}

}  // namespace aster::expr
