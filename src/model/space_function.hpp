// A load or boundary value as a function of the reference position and time:
// a constant (AFFE_CHAR_MECA) or a function of some of X, Y, Z, INST
// (AFFE_CHAR_MECA_F). Parameters are matched by name once, not per evaluation.
// A follower pressure may also depend on the current position of the point
// (code_aster's XF, YF, ZF): its value then comes with its derivatives in
// them, for the tangent.
#pragma once
#include <array>
#include <string>

#include "expr/function.hpp"

namespace aster::expr {
class Expression;
class Tabulated;
}  // namespace aster::expr

namespace aster::model {

class SpaceFunction {
 public:
  SpaceFunction() = default;
  explicit SpaceFunction(double constant) : constant_(constant) {}
  // Throws aster::Error when f has a parameter other than X, Y, Z, INST (and
  // XF, YF, ZF when currentPosition is allowed).
  explicit SpaceFunction(expr::FunctionPtr f, bool currentPosition = false);

  double operator()(double x, double y, double z, double t) const {
    if (!f_) return constant_;
    const double all[kSlots] = {x, y, z, t, 0.0, 0.0, 0.0};
    double args[kSlots];
    for (int i = 0; i < count_; ++i) args[i] = all[slot_[i]];
    return f_->evaluate(args);
  }
  // The value at reference (x, y), current (xf, yf) and time t, and its exact
  // derivatives in xf and yf (gradient, never null). Throws aster::Error when the
  // value is not a finite number.
  double atCurrentPosition(double x, double y, double t, double xf, double yf, double* gradient) const;
  // As operator(), but throws aster::Error when the value is not a finite number:
  // a FORMULE says which operation failed (log of a negative, division by zero...).
  double checked(double x, double y, double z, double t) const;
  bool isConstant() const { return !f_; }
  bool dependsOnTime() const;
  bool dependsOnCurrentPosition() const;
  const expr::FunctionPtr& function() const { return f_; }

 private:
  double constant_ = 0.0;
  expr::FunctionPtr f_;
  // f_ as what it is, found once: the checked and differentiated evaluations need it.
  const expr::Expression* expression_ = nullptr;
  const expr::Tabulated* tabulated_ = nullptr;
  static constexpr int kSlots = 7;  // X, Y, Z, INST, XF, YF, ZF
  std::array<int, kSlots> slot_{};  // parameter i of f_ is slot_[i] (0 X, 1 Y, 2 Z, 3 INST, 4 XF, 5 YF, 6 ZF)
  int count_ = 0;
};

}  // namespace aster::model
