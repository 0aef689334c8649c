// Lemaitre's viscoplasticity coupled with isotropic damage: code_aster's
// VISC_ENDO_LEMA (R5.03.15), with DEFI_MATERIAU's ELAS (E, NU), LEMAITRE (N,
// UN_SUR_K, UN_SUR_M) and VISC_ENDO (SY, R_D, A_D).
//
// With D the damage, the effective stress sigma~ = sigma / (1 - D), s its
// deviator, (.)_eq = sqrt(3/2 (.):(.)), K = 1/UN_SUR_K and 1/M = UN_SUR_M:
//   sigma       = (1 - D) E : (eps - eps_vp)
//   r'          = < (sigma~_eq - SY) / (K r^(1/M)) >^N    (r: ECROISOT)
//   eps_vp'     = r' / (1 - D) 3/2 s~ / sigma~_eq,  p' = r' / (1 - D)   (p: EPSPEQ)
//   D'          = (sigma~_eq / A_D)^R_D   while the material flows (r' > 0)
// integrated by implicit Euler over the increment, as code_aster's (whatever
// PARM_THETA: its integration of this law never reads it). With q the von Mises
// stress of the effective trial deviator s_e = s_n / (1 - D_n) + 2 mu de and
// x = dr, the step reduces to one equation:
//   G(x) = (1 - D(x)) (q - sigma~(x)) - 3 mu x = 0,
//   sigma~(x) = K (x / dt)^(1/N) (r_n + x)^(1/M) + SY,  D(x) = D_n + dt (sigma~(x) / A_D)^R_D,
// solved in u = x^(1/N) (smooth at x = 0) by Newton kept inside a bracket by
// bisection. G falls from G(0) = (1 - D_n)(q - SY) > 0 while D < 1 and sigma~ < q,
// so the root is unique. ALGO_INTE's SECANTE, BRENT and DEKKER are code_aster's
// one-dimensional solvers of that same equation; the answer does not depend on
// which one (to RESI_INTE_RELA). Then
//   s = (1 - D) sigma~ s_e / q,   tr(sigma) = (1 - D) (tr(sigma_n) / (1 - D_n) + 3 bulk tr(de)).
// When D reaches 0.99 the point is broken, as code_aster's: D = 0.99, no flow
// in that step (elastic with the damaged stiffness).
//
// The consistent tangent dsigma/deps is exact; it is not symmetric where damage
// grows (its hydrostatic part depends on dD/dq): the element mirrors one
// triangle, as code_aster does for this law (symmetric storage).
//
// Internal variables, as code_aster orders and stores them:
//   V1-V6 EPSPXX, EPSPYY, EPSPZZ, EPSPXY, EPSPXZ, EPSPYZ: eps_vp, the shear
//         components times sqrt(2) (code_aster's storage for this law)
//   V7 EPSPEQ (p), V8 ECROISOT (r), V9 ENDO (D),
//   V10 INDIPLAS: the local iterations of the step (0 when it is elastic).
// 3D-like states of AXIS and D_PLAN only (code_aster has no C_PLAN for it).
#pragma once
#include <string>
#include <vector>

#include "mechanics/behaviour_law.hpp"

namespace aster::mechanics {

struct ViscEndoLemaitreParameters {
  double young = 0, poisson = 0;
  double n = 1;           // LEMAITRE's N
  double k = 1;           // 1 / LEMAITRE's UN_SUR_K
  double oneOverM = 0;    // LEMAITRE's UN_SUR_M
  double yield = 0;       // VISC_ENDO's SY
  double rD = 1, aD = 1;  // VISC_ENDO's R_D, A_D
  // COMPORTEMENT's ITER_INTE_MAXI and RESI_INTE_RELA (the scalar equation's residual
  // relative to G(0)).
  int maxIterations = 20;
  double tolerance = 1e-6;
};

// The parameters from DEFI_MATERIAU's data, checked; throws aster::Error naming the keyword.
ViscEndoLemaitreParameters viscEndoLemaitreParameters(double young, double poisson, double n, double unSurK,
                                                      double unSurM, double yield, double rD, double aD);

class ViscEndoLemaitre final : public BehaviourLaw {
 public:
  static constexpr double kDamageMax = 0.99;  // code_aster's broken state

  // Throws aster::Error in C_PLAN and for parameters out of range.
  ViscEndoLemaitre(ViscEndoLemaitreParameters parameters, PlaneHypothesis hypothesis);

  PlaneHypothesis hypothesis() const override { return hypothesis_; }
  int internalVariableCount() const override { return 10; }
  bool predictsFromAcceptedState() const override { return true; }
  std::vector<std::string> internalVariableNames() const override;
  // Throws aster::Error when the scalar equation is not solved within ITER_INTE_MAXI
  // iterations (the driver then cuts the step).
  void integrate(const LawInput& in, LawOutput<VoigtTangent>& out, bool withTangent) const override;

  const ViscEndoLemaitreParameters& parameters() const { return parameters_; }

 private:
  ViscEndoLemaitreParameters parameters_;
  PlaneHypothesis hypothesis_;
  double mu_, bulk_;
};

}  // namespace aster::mechanics
