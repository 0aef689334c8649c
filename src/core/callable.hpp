// A scalar function supplied by the study itself (a Lua function given to
// FORMULE): kernels call it without knowing it is Lua.
#pragma once
#include <memory>

namespace aster {

class ScalarCallable {
 public:
  virtual ~ScalarCallable() = default;
  virtual double call(const double* args, int count) const = 0;
};

using CallablePtr = std::shared_ptr<const ScalarCallable>;

}  // namespace aster
