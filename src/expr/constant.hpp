// DEFI_CONSTANTE: a function whose value is the same at every abscissa. Its one
// parameter is code_aster's TOUTPARA ("any parameter"): it may be evaluated as a
// function of INST, X or anything else, with any argument.
#pragma once
#include <string>
#include <vector>

#include "expr/function.hpp"

namespace aster::expr {

inline const std::string kAnyParameter = "TOUTPARA";

class Constant : public Function {
 public:
  explicit Constant(double value) : value_(value) {}
  const std::vector<std::string>& parameters() const override { return parameter_; }
  double evaluate(const double*) const override { return value_; }
  double value() const { return value_; }

 private:
  double value_;
  std::vector<std::string> parameter_{kAnyParameter};
};

// True when f takes the parameter `name`: f's only parameter is `name`, or f takes any.
bool takesOnly(const Function& f, const std::string& name);

}  // namespace aster::expr
