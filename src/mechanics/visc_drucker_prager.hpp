// VISC_DRUC_PRAG: viscoplastic non-associated Drucker-Prager law with Perzyna
// creep, for rocks (code_aster's R7.01.22).
//
// With s the deviatoric stress, q = sqrt(3/2 s:s), I1 = tr(sigma) and p the
// cumulated viscoplastic strain:
//   yield function   f = q + alpha(p) I1 - R(p)
//   flow potential   G = q + beta(p) I1   (non-associated: beta is not alpha)
//   Perzyna rate     dp/dt = A <f / PREF>^N
//   flow             d eps_vp = dp dG/dsigma = dp (3/2 s / q + beta 1)
// alpha, R and beta are piecewise linear in p: from their _0 values at p = 0 to
// their _PIC values at P_PIC, to their _ULT values at P_ULT, constant beyond.
//
// The step is integrated by the implicit Euler scheme from the elastic trial
// state (q_e, I1_e), as code_aster does: q = q_e - 3 mu dp, I1 = I1_e - 9 K beta dp,
// and the criterion, with alpha, R and beta developed to first order in dp from
// their values at the step's start (exact while p stays on one linear piece),
//   dp = A dt / PREF^N < f1 - f2 dp - f3 dp^2 - f4 dp^3 >^N,
//   f1 = q_e + alpha_n I1_e - R_n,  f2 = 3 mu + R' - alpha' I1_e + 9 K alpha_n beta_n,
//   f3 = 9 K (alpha_n beta' + beta_n alpha'),  f4 = 9 K alpha' beta',
// is solved by Newton's method kept in [0, A dt <f1 / PREF>^N] by bisection, to
// |residual| <= RESI_INTE_RELA times its value at dp = 0, in at most
// ITER_INTE_MAXI iterations. The slopes alpha', R', beta' are those of the piece
// where the step ends (found by solving again when dp leaves the starting piece,
// the state code_aster's Newton iterations settle on); beta in the final stress
// is beta(p + dp). The step is viscoplastic when the trial state has f > 0.
//
// The tangent is the exact derivative of this integration, symmetrized
// ((D + D^T) / 2, as code_aster does for this law: its element matrices are
// symmetric); exactTangent() gives the unsymmetrized one. With no strain
// increment (a step's prediction) the tangent is the elastic one, as code_aster's
// RIGI_MECA_TANG for this law.
//
// Internal variables, as code_aster orders them: V1 EPSPEQ (p), V2 INDIPLAS (1 if
// the step was viscoplastic), V3 POS (1 before P_PIC, 2 before P_ULT, 3 beyond),
// V4 NBITER (the local iterations of the step, 0 when elastic).
// 3D, AXIS and D_PLAN (no plane stress), small strains.
#pragma once
#include <string>
#include <vector>

#include "mechanics/behaviour_law.hpp"

namespace aster::mechanics {

// DEFI_MATERIAU's VISC_DRUC_PRAG.
struct ViscDruckerPragerMaterial {
  double pref = 0, a = 0, n = 0;  // PREF, A, N
  double pPeak = 0, pUlt = 0;     // P_PIC, P_ULT
  double alpha0 = 0, alphaPeak = 0, alphaUlt = 0;
  double r0 = 0, rPeak = 0, rUlt = 0;
  double beta0 = 0, betaPeak = 0, betaUlt = 0;
};

struct ViscDruckerPragerParameters {
  double young = 0, poisson = 0;
  ViscDruckerPragerMaterial material;
  int maxIterations = 20;   // ITER_INTE_MAXI
  double tolerance = 1e-6;  // RESI_INTE_RELA
};

// alpha, R, beta at p, and the slopes of the piece p lies on (0 for p >= P_ULT).
struct DruckerPragerHardening {
  double alpha, r, beta;
};
// The piece of p: 0 below P_PIC, 1 below P_ULT, 2 beyond.
int hardeningPiece(const ViscDruckerPragerMaterial& m, double p);
DruckerPragerHardening hardeningValues(const ViscDruckerPragerMaterial& m, double p);
DruckerPragerHardening hardeningSlopes(const ViscDruckerPragerMaterial& m, int piece);

class ViscDruckerPrager final : public BehaviourLaw {
 public:
  // Throws aster::Error for parameters out of range (E > 0, -1 < NU < 0.5,
  // PREF > 0, A >= 0, N > 0, 0 < P_PIC < P_ULT) and for plane stress.
  ViscDruckerPrager(ViscDruckerPragerParameters parameters, PlaneHypothesis hypothesis);

  PlaneHypothesis hypothesis() const override { return hypothesis_; }
  int internalVariableCount() const override { return 4; }
  bool predictsFromAcceptedState() const override { return true; }
  std::vector<std::string> internalVariableNames() const override;
  // Throws aster::Error when the local Newton does not converge, or the return
  // would cross the apex of the cone (the driver then cuts the step).
  void integrate(const LawInput& in, LawOutput<VoigtTangent>& out, bool withTangent) const override;
  // The derivative of the stress integrate() computes with respect to the strain
  // (Voigt, unsymmetrized), to check against finite differences.
  VoigtTangent exactTangent(const LawInput& in) const;

  const ViscDruckerPragerParameters& parameters() const { return parameters_; }

 private:
  // The step from the previous state with the strain increment de (tensor
  // components xx, yy, zz, xy); writes stress, variables and the unsymmetrized
  // tangent when asked.
  void update(const LawInput& in, const double de[4], double stress[4], double* variables,
              VoigtTangent* tangent) const;
  // dp of a viscoplastic step; nbIter the iterations taken. f1: the trial criterion.
  double solve(double f1, double i1e, double dt, const DruckerPragerHardening& atStart,
               const DruckerPragerHardening& slopes, int& nbIter) const;

  ViscDruckerPragerParameters parameters_;
  PlaneHypothesis hypothesis_;
  double mu_, bulk_;
};

}  // namespace aster::mechanics
