// A load or boundary value as a function of the reference position and time:
// a constant (AFFE_CHAR_MECA) or a function of some of X, Y, Z, INST
// (AFFE_CHAR_MECA_F). Parameters are matched by name once, not per evaluation.
#pragma once
#include <array>
#include <string>

#include "expr/function.hpp"

namespace aster::model {

class SpaceFunction {
 public:
  SpaceFunction() = default;
  explicit SpaceFunction(double constant) : constant_(constant) {}
  // Throws aster::Error when f has a parameter other than X, Y, Z, INST.
  explicit SpaceFunction(expr::FunctionPtr f);

  double operator()(double x, double y, double z, double t) const {
    if (!f_) return constant_;
    const double all[4] = {x, y, z, t};
    double args[4];
    for (int i = 0; i < count_; ++i) args[i] = all[slot_[i]];
    return f_->evaluate(args);
  }
  // As operator(), but throws aster::Error when the value is not a finite number:
  // a FORMULE says which operation failed (log of a negative, division by zero...).
  double checked(double x, double y, double z, double t) const;
  bool isConstant() const { return !f_; }
  bool dependsOnTime() const;
  const expr::FunctionPtr& function() const { return f_; }

 private:
  double constant_ = 0.0;
  expr::FunctionPtr f_;
  std::array<int, 4> slot_{};  // parameter i of f_ is coordinate slot_[i] (0 X, 1 Y, 2 Z, 3 INST)
  int count_ = 0;
};

}  // namespace aster::model
