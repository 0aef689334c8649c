// Linear isotropic elasticity in the plane (ELAS), per unit thickness, the same
// law for the small-strain (PETIT) and the Saint Venant-Kirchhoff (GROT_GDEP)
// kinematics:
//   stress = lambda' tr(e) I + 2 mu e  on the in-plane 2x2 strain e,
// with lambda' = lambda for plane strain (D_PLAN) and
// lambda' = 2 lambda mu / (lambda + 2 mu) for plane stress (C_PLAN, sigma_zz = 0;
// with GROT_GDEP this is Saint Venant-Kirchhoff with S_zz = 0, whose E_zz =
// -lambda/(lambda + 2 mu) tr(E) is linear: the condensed law is exact). In AXIS the
// zz strain is the hoop strain e_zz, given: stress = lambda (tr e + e_zz) I + 2 mu e,
// s_zz = lambda (tr e + e_zz) + 2 mu e_zz (the 4-component integrate() only).
// The program's one source of the Lame constants.
#pragma once
#include <Eigen/Core>

#include "mechanics/behaviour_law.hpp"
#include "mechanics/modelling.hpp"

namespace aster::mechanics {

// The tangent of this law, lambda' I x I + 2 mu I_sym: the element contracts it
// with the strain variations in a third of the flops of a general VoigtTangent.
struct IsotropicTangent {
  double lambda = 0;  // lambda'
  double mu = 0;
};

class IsotropicElasticity final : public BehaviourLaw {
 public:
  using Tangent = IsotropicTangent;
  static constexpr bool kUsesHistory = false;

  // Throws aster::Error unless young > 0 and -1 < poisson < 0.5.
  IsotropicElasticity(double young, double poisson, PlaneHypothesis hypothesis);

  double young() const { return young_; }
  double poisson() const { return poisson_; }
  PlaneHypothesis hypothesis() const override { return hypothesis_; }
  double lambda() const { return lambda_; }            // 3D Lame constants
  double mu() const { return mu_; }
  double planeLambda() const { return planeLambda_; }  // lambda' above

  // In-plane stress of a symmetric in-plane strain.
  Eigen::Matrix2d stress(const Eigen::Matrix2d& strain) const {
    return planeLambda_ * strain.trace() * Eigen::Matrix2d::Identity() + 2 * mu_ * strain;
  }
  // The zz stress: lambda tr(e) in plane strain (e_zz = 0), zero in plane stress.
  // e_zz: 0 in D_PLAN, the one making s_zz = 0 in C_PLAN.
  double outOfPlaneStrain(const Eigen::Matrix2d& strain) const {
    return hypothesis_ == PlaneHypothesis::PlaneStress ? -lambda_ / (lambda_ + 2 * mu_) * strain.trace() : 0.0;
  }
  double outOfPlaneStress(const Eigen::Matrix2d& strain) const {
    return hypothesis_ == PlaneHypothesis::PlaneStress ? 0.0 : lambda_ * strain.trace();
  }
  // Voigt matrix for (e_xx, e_yy, e_zz, 2 e_xy) -> (s_xx, s_yy, s_zz, s_xy); in
  // C_PLAN condensed on s_zz = 0 (zz row and column zero).
  const VoigtTangent& voigt() const { return voigt_; }

  int internalVariableCount() const override { return 0; }
  // The form the element kernels inline, for D_PLAN and C_PLAN (e_zz = 0 or not read).
  void integrate(const LawInput& in, LawOutput<IsotropicTangent>& out, bool withTangent) const {
    out.stress = stress(in.strain);
    out.stressZZ = outOfPlaneStress(in.strain);
    out.strainZZ = outOfPlaneStrain(in.strain);
    if (withTangent) out.tangent = {planeLambda_, mu_};
  }
  void integrate(const LawInput& in, LawOutput<VoigtTangent>& out, bool withTangent) const override;

 private:
  double young_, poisson_;
  PlaneHypothesis hypothesis_;
  double lambda_, mu_, planeLambda_;
  VoigtTangent voigt_;
};

}  // namespace aster::mechanics
