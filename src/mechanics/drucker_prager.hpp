// Drucker-Prager plasticity of soils: code_aster's DRUCK_PRAGER (associated) and
// DRUCK_PRAG_N_A (non-associated), R7.01.16, integrated implicitly (ALGO_INTE
// ANALYTIQUE: a scalar equation in the plastic multiplier, solved to rounding).
//
// With s the deviatoric stress, q = sqrt(3/2 s:s), I1 = tr(sigma) and p the
// cumulated plastic strain (the plastic multiplier):
//   yield function  f = q + A I1 - R(p),  A = ALPHA
//   flow            d eps_p = dp (3/2 s / q + B 1)
//     DRUCK_PRAGER:   B = A (associated);
//     DRUCK_PRAG_N_A: B(p) = DILAT (1 - p / P_ULTM) before P_ULTM, 0 after, taken at
//                     the end of the step.
//   hardening (DRUCK_PRAGER's ECROUISSAGE), frozen past P_ULTM:
//     LINEAIRE:    R(p) = SY + H min(p, P_ULTM)
//     PARABOLIQUE: R(p) = SY (1 - (1 - sqrt(SY_ULTM / SY)) min(p, P_ULTM) / P_ULTM)^2
// Return to the cone from the elastic trial state (q_e, I1_e):
//   q_e - 3 mu dp + A (I1_e - 9 K B dp) = R(p_n + dp);
// when that leaves q = q_e - 3 mu dp < 0, the return to the apex (s = 0):
//   A (I1_e - 9 K B dp) = R(p_n + dp).
// Either way I1 = I1_e - 9 K B dp and EPSPVOL grows by 3 B dp.
// The consistent tangent, on the cone
//   D = K 1x1 + 2 mu (1 - 3 mu dp / q_e) I_dev + 9 mu^2 dp / q_e^3 s_e x s_e - w x v / h,
//   v = 3 mu s_e / q_e + 3 K A 1 (the yield gradient), w = 3 mu s_e / q_e + 3 K (B + B' dp) 1
//   (the flow's), h = 3 mu + 9 K A (B + B' dp) + R';
// at the apex D = K (1 - 9 K A (B + B' dp) / h_a) 1x1, h_a = 9 K A (B + B' dp) + R'.
// w = v for DRUCK_PRAGER (a symmetric tangent); DRUCK_PRAG_N_A's is not symmetric.
// At the apex past P_ULTM (nothing left to harden) the exact tangent is zero; the law
// gives code_aster's stand-in there, the elastic tangent of E / 1e6.
//
// Internal variables, as code_aster orders them: V1 EPSPEQ (p), V2 EPSPVOL (the
// volumetric plastic strain), V3 INDIPLAS (0 elastic, 1 on the cone, 2 at the apex).
// 3D laws: D_PLAN and AXIS (code_aster has no C_PLAN for them); the strain may be
// small (PETIT) or Green-Lagrange (GROT_GDEP, the law then in E and S).
#pragma once
#include <string>
#include <vector>

#include "mechanics/behaviour_law.hpp"

namespace aster::mechanics {

struct DruckerPragerParameters {
  enum class Hardening { Linear, Parabolic };
  double young = 0, poisson = 0;
  double alpha = 0;            // ALPHA (A)
  double yield = 0;            // SY
  double ultimateStrain = 0;   // P_ULTM
  Hardening hardening = Hardening::Linear;
  double slope = 0;            // H (LINEAIRE)
  double ultimateYield = 0;    // SY_ULTM (PARABOLIQUE)
  bool associated = true;      // DRUCK_PRAGER; false: DRUCK_PRAG_N_A
  double dilatancy = 0;        // DILAT (DRUCK_PRAG_N_A)

  // R(p), dR/dp (the right slope at P_ULTM).
  double radius(double p) const;
  double radiusSlope(double p) const;
  // B(p) and dB/dp (the flow's volumetric part).
  double flowVolumetric(double p) const;
  double flowVolumetricSlope(double p) const;
};

class DruckerPrager final : public BehaviourLaw {
 public:
  // Throws aster::Error for parameters out of range (E > 0, -1 < NU < 0.5, SY > 0,
  // P_ULTM > 0, SY_ULTM > 0), for C_PLAN, and for DRUCK_PRAG_N_A with linear hardening
  // (code_aster has it with the parabolic one only).
  DruckerPrager(DruckerPragerParameters parameters, PlaneHypothesis hypothesis);

  PlaneHypothesis hypothesis() const override { return hypothesis_; }
  int internalVariableCount() const override { return 3; }
  std::vector<std::string> internalVariableNames() const override { return {"EPSPEQ", "EPSPVOL", "INDIPLAS"}; }
  bool symmetricTangent() const override { return parameters_.associated; }
  // Throws aster::Error when the return equation has no solution (the step is then cut).
  void integrate(const LawInput& in, LawOutput<VoigtTangent>& out, bool withTangent) const override;

  const DruckerPragerParameters& parameters() const { return parameters_; }

 private:
  // The plastic multiplier dp > 0 solving residual(dp) = 0, residual(0) > 0: Newton
  // safeguarded by bisection.
  template <class Residual>
  double solveReturn(const Residual& residual, double scale) const;

  DruckerPragerParameters parameters_;
  PlaneHypothesis hypothesis_;
  double mu_, bulk_;
};

}  // namespace aster::mechanics
