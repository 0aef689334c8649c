// Linear isotropic elasticity in the plane (per unit thickness), shared by the
// small-strain (PETIT) and the Saint Venant-Kirchhoff (GROT_GDEP) kinematics:
//   stress = lambda' tr(e) I + 2 mu e  on the in-plane 2x2 strain e,
// with lambda' = lambda for plane strain (D_PLAN) and
// lambda' = 2 lambda mu / (lambda + 2 mu) for plane stress (C_PLAN, sigma_zz = 0).
#pragma once
#include <Eigen/Core>

namespace aster::mechanics {

enum class PlaneHypothesis { PlaneStrain, PlaneStress };      // D_PLAN, C_PLAN
enum class Kinematics { SmallStrain, TotalLagrangianSVK };    // PETIT, GROT_GDEP

class PlaneElasticity {
 public:
  // Throws aster::Error unless young > 0 and -1 < poisson < 0.5.
  PlaneElasticity(double young, double poisson, PlaneHypothesis hypothesis);

  double young() const { return young_; }
  double poisson() const { return poisson_; }
  PlaneHypothesis hypothesis() const { return hypothesis_; }
  double lambda() const { return lambda_; }            // 3D Lame constants
  double mu() const { return mu_; }
  double planeLambda() const { return planeLambda_; }  // lambda' above

  // In-plane stress of a symmetric in-plane strain.
  Eigen::Matrix2d stress(const Eigen::Matrix2d& strain) const {
    return planeLambda_ * strain.trace() * Eigen::Matrix2d::Identity() + 2 * mu_ * strain;
  }
  // The zz stress: lambda tr(e) in plane strain (e_zz = 0), zero in plane stress.
  double outOfPlaneStress(const Eigen::Matrix2d& strain) const {
    return hypothesis_ == PlaneHypothesis::PlaneStrain ? lambda_ * strain.trace() : 0.0;
  }
  // Voigt matrix for (e_xx, e_yy, 2 e_xy) -> (s_xx, s_yy, s_xy).
  const Eigen::Matrix3d& voigt() const { return voigt_; }

 private:
  double young_, poisson_;
  PlaneHypothesis hypothesis_;
  double lambda_, mu_, planeLambda_;
  Eigen::Matrix3d voigt_;
};

}  // namespace aster::mechanics
