#include "mechanics/isotropic_elasticity.hpp"

#include <string>

#include "core/error.hpp"

namespace aster::mechanics {

IsotropicElasticity::IsotropicElasticity(double young, double poisson, PlaneHypothesis hypothesis)
    : young_(young), poisson_(poisson), hypothesis_(hypothesis) {
  if (!(young > 0)) throw Error("elastic material: Young's modulus E must be > 0, got " + std::to_string(young));
  if (!(poisson > -1 && poisson < 0.5))
    throw Error("elastic material: Poisson's ratio NU must be in (-1, 0.5), got " + std::to_string(poisson));
  lambda_ = young * poisson / ((1 + poisson) * (1 - 2 * poisson));
  mu_ = young / (2 * (1 + poisson));
  planeLambda_ = hypothesis == PlaneHypothesis::PlaneStrain ? lambda_ : 2 * lambda_ * mu_ / (lambda_ + 2 * mu_);
  voigt_ << planeLambda_ + 2 * mu_, planeLambda_, 0,  //
      planeLambda_, planeLambda_ + 2 * mu_, 0,        //
      0, 0, mu_;
}

void IsotropicElasticity::integrate(const LawInput& in, LawOutput<VoigtTangent>& out, bool withTangent) const {
  out.stress = stress(in.strain);
  out.stressZZ = outOfPlaneStress(in.strain);
  if (withTangent) out.tangent = voigt_;
}

}  // namespace aster::mechanics
