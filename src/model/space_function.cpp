#include "model/space_function.hpp"
#include "core/number_format.hpp"

#include <cmath>

#include "core/error.hpp"
#include "expr/constant.hpp"
#include "expr/dual.hpp"
#include "expr/expression.hpp"
#include "expr/tabulated.hpp"

namespace aster::model {

SpaceFunction::SpaceFunction(expr::FunctionPtr f, bool currentPosition) : f_(std::move(f)) {
  const auto& params = f_->parameters();
  const char* allowed = currentPosition ? "X, Y, Z, INST, XF, YF and ZF" : "X, Y, Z and INST";
  if (params.size() > static_cast<std::size_t>(currentPosition ? kSlots : 4))
    throw Error(std::string("a load function takes at most ") + allowed + ", got " + expr::joinNames(params));
  count_ = static_cast<int>(params.size());
  static const char* const names[kSlots] = {"X", "Y", "Z", "INST", "XF", "YF", "ZF"};
  for (int i = 0; i < count_; ++i) {
    const std::string& p = params[i];
    slot_[i] = -1;
    for (int s = 0; s < (currentPosition ? kSlots : 4); ++s)
      if (p == names[s]) slot_[i] = s;
    if (p == expr::kAnyParameter) slot_[i] = 0;  // a constant: any argument
    if (slot_[i] >= 0) continue;
    if (!currentPosition && (p == "XF" || p == "YF" || p == "ZF"))
      throw Error("the parameter '" + p + "' is the current position of the point: only a follower "
                  "pressure (PRES_REP applied with TYPE_CHARGE='SUIV') may depend on it");
    throw Error(std::string("a load function may depend on ") + allowed + " only; its parameter '" + p +
                "' is none of them");
  }
  expression_ = dynamic_cast<const expr::Expression*>(f_.get());
  tabulated_ = dynamic_cast<const expr::Tabulated*>(f_.get());
  if (dependsOnCurrentPosition() && !expression_ && !tabulated_)
    throw Error("a function of XF, YF or ZF must be a FORMULE or a DEFI_FONCTION (its derivatives are needed)");
}

double SpaceFunction::atCurrentPosition(double x, double y, double t, double xf, double yf,
                                        double* gradient) const {
  gradient[0] = gradient[1] = 0.0;
  if (!dependsOnCurrentPosition()) return checked(x, y, 0.0, t);
  const double all[kSlots] = {x, y, 0.0, t, xf, yf, 0.0};
  double value;
  if (const auto* e = expression_) {
    using D = expr::Dual1<2>;
    D args[kSlots];
    for (int i = 0; i < count_; ++i)
      args[i] = slot_[i] == 4 ? D::variable(xf, 0) : slot_[i] == 5 ? D::variable(yf, 1) : D(all[slot_[i]]);
    double plain[kSlots];
    for (int i = 0; i < count_; ++i) plain[i] = all[slot_[i]];
    value = e->evaluateChecked(plain);  // names the failing operation, if any
    const D v = e->evaluateT<D>(args);
    gradient[0] = v.d[0];
    gradient[1] = v.d[1];
  } else {  // a DEFI_FONCTION of one current coordinate
    const auto& tab = *tabulated_;
    const double at = all[slot_[0]];
    value = tab.valueAt(at);
    if (slot_[0] == 4 || slot_[0] == 5) gradient[slot_[0] - 4] = tab.slopeAt(at);
  }
  if (!std::isfinite(value) || !std::isfinite(gradient[0]) || !std::isfinite(gradient[1]))
    throw Error("the function or its derivative is not a finite number");
  return value;
}

double SpaceFunction::checked(double x, double y, double z, double t) const {
  if (!f_) return constant_;
  const double all[kSlots] = {x, y, z, t, 0.0, 0.0, 0.0};
  double args[kSlots];
  for (int i = 0; i < count_; ++i) args[i] = all[slot_[i]];
  if (expression_) return expression_->evaluateChecked(args);
  const double v = f_->evaluate(args);
  if (!std::isfinite(v)) throw Error("the function returns " + format::shortest(v));
  return v;
}

bool SpaceFunction::dependsOnCurrentPosition() const {
  for (int i = 0; i < count_; ++i)
    if (slot_[i] >= 4) return true;
  return false;
}

bool SpaceFunction::dependsOnTime() const {
  for (int i = 0; i < count_; ++i)
    if (slot_[i] == 3) return true;
  return false;
}

}  // namespace aster::model
