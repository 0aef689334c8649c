// The logarithmic (Hencky) strain of a plane state, T = ln(C) / 2 with C = F^T F =
// I + 2 E, and its first two derivatives with respect to the Green-Lagrange strain
// E: the kinematics of code_aster's DEFORMATION='GDEF_LOG' (Miehe, Apel and
// Lambrecht 2002; code_aster R5.03.24), see log_strain_law.hpp.
//
// C is 3x3 with an in-plane 2x2 block and the out-of-plane zz component (zz is a
// principal direction), so its eigenvalues c_i and eigenvectors are found in closed
// form. With g(c) = ln(c) / 2 and, in the eigenbasis of C (Daleckii-Krein),
//   dT~_ij = g[c_i, c_j] dC~_ij,
//   d2T~_ij[H, K] = sum_k g[c_i, c_k, c_j] (H~_ik K~_kj + K~_ik H~_kj),
// where g[.,.] and g[.,.,.] are the first and second divided differences of g
// (g'(c) and g''(c)/2 on equal arguments, evaluated without cancellation on
// nearly equal ones), the derivatives hold for any eigenvalues, equal ones
// included. dC = 2 dE.
//
// Voigt conventions as in behaviour_law.hpp: strain-like quantities (E, T)
// as (11, 22, 33, 2 x 12), stress-like ones (S, the dual of T) as (11, 22, 33, 12).
#pragma once
#include <Eigen/Core>

namespace aster::mechanics {

class LogarithmicStrain {
 public:
  // From E (in-plane) and E_zz. Throws aster::Error when C = I + 2 E is not
  // positive definite (F singular, or not a number).
  LogarithmicStrain(const Eigen::Matrix2d& E, double Ezz);

  // T, in-plane and zz.
  const Eigen::Matrix2d& strain() const { return T_; }
  double strainZZ() const { return Tzz_; }

  // P = dT/dE, Voigt strain to Voigt strain: the stress conjugate to E of a stress
  // tau conjugate to T is S = P^T tau (S_J = tau_I P_IJ).
  Eigen::Matrix4d projector() const;
  // The 4x4 symmetric matrix tau : d2T/dE2 (Voigt strain on both sides), for the
  // stress tau conjugate to T (Voigt stress: tau11, tau22, tau33, tau12).
  Eigen::Matrix4d stressCurvature(const Eigen::Vector4d& tau) const;

 private:
  // g[c_i, c_j] (symmetric).
  Eigen::Matrix3d firstDifferences() const;
  // The variation of C for a unit variation of E's Voigt component b, in C's eigenbasis.
  Eigen::Matrix3d eigenbasisVariation(int b) const;

  double e_[3];        // eigenvalues of E, in-plane (2) and zz; those of C are 1 + 2 e (with exact differences)
  Eigen::Matrix3d Q_;  // eigenvectors of C, column i for c_i
  Eigen::Matrix2d T_;
  double Tzz_;
};

}  // namespace aster::mechanics
