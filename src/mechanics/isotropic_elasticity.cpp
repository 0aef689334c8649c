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
  const bool planeStress = hypothesis == PlaneHypothesis::PlaneStress;
  planeLambda_ = planeStress ? 2 * lambda_ * mu_ / (lambda_ + 2 * mu_) : lambda_;
  const double zz = planeStress ? 0.0 : lambda_ + 2 * mu_, coupling = planeStress ? 0.0 : lambda_;
  voigt_ << planeLambda_ + 2 * mu_, planeLambda_, coupling, 0,  //
      planeLambda_, planeLambda_ + 2 * mu_, coupling, 0,        //
      coupling, coupling, zz, 0,                                //
      0, 0, 0, mu_;
}

void IsotropicElasticity::integrate(const LawInput& in, LawOutput<VoigtTangent>& out, bool withTangent) const {
  if (hypothesis_ == PlaneHypothesis::PlaneStress) {
    out.stress = stress(in.strain);
    out.stressZZ = 0.0;
    out.strainZZ = outOfPlaneStrain(in.strain);
  } else {
    const double ezz = in.strainZZ;  // 0 in D_PLAN
    const double volume = lambda_ * (in.strain.trace() + ezz);
    out.stress = volume * Eigen::Matrix2d::Identity() + 2 * mu_ * in.strain;
    out.stressZZ = volume + 2 * mu_ * ezz;
    out.strainZZ = ezz;
  }
  if (withTangent) out.tangent = voigt_;
}

}  // namespace aster::mechanics
