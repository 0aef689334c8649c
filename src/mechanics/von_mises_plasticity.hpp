// Von Mises plasticity with isotropic and linear kinematic (Prager) hardening:
// code_aster's VMIS_ISOT_LINE, VMIS_ISOT_TRAC, VMIS_CINE_LINE, VMIS_ECMI_LINE and
// VMIS_ECMI_TRAC (R5.03.02, R5.03.16), one class.
//
// With s the deviatoric stress, X the back stress (deviatoric), p the cumulated
// plastic strain and (.)_eq = sqrt(3/2 (.):(.)):
//   yield function  f = (s - X)_eq - R(p)
//   flow            d eps_p = dp n,  n = 3/2 (s - X) / (s - X)_eq
//   hardening       dX = C d eps_p   (C: PRAGER's C, or 2/3 H for VMIS_CINE_LINE)
// integrated by the radial return from the trial state s_n + 2 mu de (implicit
// Euler, exact for linear hardening), with the consistent tangent
//   D = K 1x1 + 2 mu [(1 - 3 mu dp / q) I_dev - (3 mu / (h + R') - 3 mu dp / q) N x N],
// q the trial (s - X)_eq, h = 3 mu + 1.5 C, N the unit normal (s - X)/|s - X|.
// The strain may be small (PETIT) or Green-Lagrange (GROT_GDEP, the law then in
// E and S). Plane stress (C_PLAN): the law finds the zz strain increment that
// makes s_zz = 0 by Newton on the same integration (to rounding), and returns
// the tangent condensed on s_zz = 0. With isotropic hardening alone (VMIS_ISOT_*),
// plane stress is integrated as code_aster does it instead: one scalar equation in
// dp, in which s_zz = 0 holds in closed form for any dp, solved by the secant method
// to RESI_INTE_RELA x SY (the yield condition holds to that tolerance).
//
// Internal variables per Gauss point, as code_aster orders them:
//   Isotropic (VMIS_ISOT_*):   V1 EPSPEQ (p), V2 INDIPLAS (1 if the step was plastic)
//   Kinematic (VMIS_CINE_LINE): V1-V6 XCINXX, XCINYY, XCINZZ, XCINXY, XCINXZ, XCINYZ
//                               (X, tensor components), V7 INDIPLAS, V8 EPSPEQ
//   Mixed (VMIS_ECMI_*):       V1 EPSPEQ, V2 INDIPLAS, V3-V8 XCINXX ... XCINYZ
#pragma once
#include <string>
#include <vector>

#include "mechanics/behaviour_law.hpp"
#include "mechanics/isotropic_hardening.hpp"

namespace aster::mechanics {

enum class VonMisesVariables { Isotropic, Kinematic, Mixed };

struct VonMisesParameters {
  double young = 0, poisson = 0;
  IsotropicHardening hardening = IsotropicHardening::linear(0, 0);  // R(p), the kinematic part removed
  double prager = 0;                                                // C
  VonMisesVariables variables = VonMisesVariables::Isotropic;
  // COMPORTEMENT's ITER_INTE_MAXI and RESI_INTE_RELA: the plane stress iterations.
  int maxIterations = 20;
  double tolerance = 1e-6;
};

// The parameters of each relation from DEFI_MATERIAU's data (ELAS's E and NU,
// ECRO_LINE's D_SIGM_EPSI and SY, TRACTION's curve, PRAGER's C), with
// code_aster's conversions and checks; they throw aster::Error naming the keyword.
struct TractionCurve {
  std::vector<double> strain, stress;  // the points of TRACTION's SIGM function of EPSI
  IsotropicHardening::Beyond beyond = IsotropicHardening::Beyond::Refuse;
};
VonMisesParameters isotropicLinearParameters(double young, double poisson, double slope, double yield);
VonMisesParameters isotropicTractionParameters(double poisson, const TractionCurve& curve);  // E from the curve
VonMisesParameters kinematicLinearParameters(double young, double poisson, double slope, double yield);
VonMisesParameters mixedLinearParameters(double young, double poisson, double slope, double yield, double prager);
VonMisesParameters mixedTractionParameters(double poisson, const TractionCurve& curve, double prager);

class VonMisesPlasticity final : public BehaviourLaw {
 public:
  // Throws aster::Error for parameters out of range (E > 0, -1 < NU < 0.5, C >= 0, R(0) > 0).
  VonMisesPlasticity(VonMisesParameters parameters, PlaneHypothesis hypothesis);

  PlaneHypothesis hypothesis() const override { return hypothesis_; }
  int internalVariableCount() const override;
  std::vector<std::string> internalVariableNames() const override;
  // Throws aster::Error when the plane stress iterations do not converge or the
  // hardening curve ends (the driver then cuts the step).
  void integrate(const LawInput& in, LawOutput<VoigtTangent>& out, bool withTangent) const override;

  const VonMisesParameters& parameters() const { return parameters_; }

 private:
  // The 3D return from the previous state with the strain increment de (tensor
  // components xx, yy, zz, xy); writes stress, variables and the full 4x4 tangent.
  // atRest: no increment (a step's prediction), where the tangent after a plastic
  // step is the continuum elastic-plastic one, as code_aster's.
  void returnMap(const LawInput& in, const double de[4], bool atRest, double stress[4], double* variables,
                 VoigtTangent* tangent, bool& plastic) const;
  // Plane stress with isotropic hardening alone, as code_aster integrates it: de[2]
  // (the zz increment) comes in as the elastic guess; the return solves one scalar
  // yield equation in dp, the zz strain following from s_zz = 0 in closed form, to
  // within RESI_INTE_RELA x SY. Writes stress, variables and the condensed tangent.
  // atRest (a step's prediction): after a plastic step, the continuum tangent at the
  // previous stress, as code_aster's RIGI_MECA_TANG.
  void planeStressIsotropicReturn(const LawInput& in, double de[4], bool atRest, double stress[4],
                                  double* variables, VoigtTangent* tangent) const;

  VonMisesParameters parameters_;
  PlaneHypothesis hypothesis_;
  double mu_, bulk_;
};

}  // namespace aster::mechanics
