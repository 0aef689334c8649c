// Hyperelasticity of the generalised Mooney-Rivlin (Signorini) kind: code_aster's
// ELAS_HYPER (R5.03.19), DEFI_MATERIAU's C10, C01, C20 and K (or NU), with the
// total Lagrangian kinematics only (GROT_GDEP: Green-Lagrange E in, second
// Piola-Kirchhoff S out).
//
// With C = 2E + I (3x3), J = sqrt(det C), the invariants I1 = tr C,
// I2 = (I1^2 - tr(C^2)) / 2 and their isochoric forms I1~ = J^(-2/3) I1,
// I2~ = J^(-4/3) I2, the stored energy per unit reference volume is
//   W = C10 (I1~ - 3) + C01 (I2~ - 3) + C20 (I1~ - 3)^2 + K/2 (J - 1)^2
// and S = 2 dW/dC, dS/dE = 4 d2W/dC2, both computed analytically. At E = 0 the
// tangent is isotropic elasticity with mu = 2 (C10 + C01) and the bulk modulus K.
//
// D_PLAN: E33 = 0. C_PLAN: the law finds E33 making S33 = 0 by Newton at the
// Gauss point and returns the tangent condensed on S33 = 0 (zz row and column
// zero); out.strainZZ reports E33. AXIS is refused (code_aster allows 3D, D_PLAN
// and C_PLAN only).
//
// One internal variable, VIDE, always 0 (code_aster keeps one to have a field).
#pragma once
#include <string>
#include <vector>

#include "mechanics/behaviour_law.hpp"
#include "mechanics/modelling.hpp"

namespace aster::mechanics {

class Hyperelasticity final : public BehaviourLaw {
 public:
  // Throws aster::Error unless c10 + c01 > 0, bulk > 0 and hypothesis is D_PLAN or C_PLAN.
  Hyperelasticity(double c10, double c01, double c20, double bulk, PlaneHypothesis hypothesis);

  // The bulk modulus K that code_aster derives from NU when K is not given, that of
  // small-strain elasticity with mu = 2 (C10 + C01): K = 4 (C10 + C01) (1 + NU) / (3 (1 - 2 NU)).
  // Throws aster::Error unless -1 < nu < 0.5.
  static double bulkFromPoisson(double c10, double c01, double nu);

  double c10() const { return c10_; }
  double c01() const { return c01_; }
  double c20() const { return c20_; }
  double bulk() const { return bulk_; }
  PlaneHypothesis hypothesis() const override { return hypothesis_; }
  int internalVariableCount() const override { return 1; }
  std::vector<std::string> internalVariableNames() const override { return {"VIDE"}; }

  // S and dS/dE from E (in.strain, in-plane) and, in D_PLAN, in.strainZZ (the
  // element gives 0; the law takes any E33, as ELAS does). Throws
  // aster::Error when det C <= 0 or the plane stress Newton does not converge.
  void integrate(const LawInput& in, LawOutput<VoigtTangent>& out, bool withTangent) const override;

 private:
  double c10_, c01_, c20_, bulk_;
  PlaneHypothesis hypothesis_;
};

}  // namespace aster::mechanics
