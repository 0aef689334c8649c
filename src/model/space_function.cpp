#include "model/space_function.hpp"
#include "core/number_format.hpp"

#include <cmath>

#include "core/error.hpp"
#include "expr/constant.hpp"
#include "expr/expression.hpp"

namespace aster::model {

SpaceFunction::SpaceFunction(expr::FunctionPtr f) : f_(std::move(f)) {
  const auto& params = f_->parameters();
  if (params.size() > 4) throw Error("a load function takes at most X, Y, Z and INST, got " +
                                     expr::joinNames(params));
  count_ = static_cast<int>(params.size());
  for (int i = 0; i < count_; ++i) {
    const std::string& p = params[i];
    if (p == "X") slot_[i] = 0;
    else if (p == "Y") slot_[i] = 1;
    else if (p == "Z") slot_[i] = 2;
    else if (p == "INST") slot_[i] = 3;
    else if (p == expr::kAnyParameter) slot_[i] = 0;  // a constant: any argument
    else throw Error("a load function may depend on X, Y, Z and INST only; its parameter '" + p +
                     "' is none of them");
  }
}

double SpaceFunction::checked(double x, double y, double z, double t) const {
  if (!f_) return constant_;
  const double all[4] = {x, y, z, t};
  double args[4];
  for (int i = 0; i < count_; ++i) args[i] = all[slot_[i]];
  if (const auto* e = dynamic_cast<const expr::Expression*>(f_.get())) return e->evaluateChecked(args);
  const double v = f_->evaluate(args);
  if (!std::isfinite(v)) throw Error("the function returns " + format::shortest(v));
  return v;
}

bool SpaceFunction::dependsOnTime() const {
  for (int i = 0; i < count_; ++i)
    if (slot_[i] == 3) return true;
  return false;
}

}  // namespace aster::model
