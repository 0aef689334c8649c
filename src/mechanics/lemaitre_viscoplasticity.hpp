// Lemaitre's viscoplasticity without threshold, and Norton's creep law, its
// case 1/M = 0: code_aster's LEMAITRE and NORTON (R5.03.08), one class.
//
// With s the deviatoric stress, (.)_eq = sqrt(3/2 (.):(.)) and p the cumulated
// viscoplastic strain:
//   dp/dt = (s_eq / (K p^(1/M)))^N,   d eps_v/dt = 3/2 dp/dt s / s_eq
// (DEFI_MATERIAU LEMAITRE: N, UN_SUR_K = 1/K, UN_SUR_M = 1/M), linear isotropic
// elasticity otherwise. The step is integrated by the theta scheme of code_aster
// (PARM_THETA = 1: implicit Euler; 0.5: the midpoint rule): the flow is taken at
// the state x_theta = x_n + theta (x_{n+1} - x_n),
//   s_theta = s_n + 2 mu theta (de - d eps_v),  d eps_v = dt 3/2 g(s_theta_eq, p_theta) s_theta / s_theta_eq,
// which makes s_theta the trial s* = s_n + 2 mu theta de scaled by x / s*_eq,
// x = s_theta_eq the root of the scalar equation
//   x - s*_eq + 3 mu theta dt g(x, p_n + (s*_eq - x) / (3 mu)) = 0,
// and then s_{n+1} = s_n + (s_theta - s_n) / theta, p_{n+1} = p_n + dp,
// dp = (s*_eq - x) / (3 mu theta). The mean stress is elastic. As code_aster
// (ALGO_INTE='DEKKER'), the root is found by regula falsi with a bisection every
// third trial, stopped when |F| < RESI_INTE_RELA (stress units), and s_theta is
// s* x / (x + 3 mu theta dt g(x)) (s* x / s*_eq at the exact root): the answers
// agree with code_aster's to its tolerance, not merely to the exact root's. The
// tangent d sigma_{n+1} / d eps_{n+1} is the exact derivative at the root
// (symmetric), as code_aster's.
// The strain may be small (PETIT) or Green-Lagrange (GROT_GDEP, the law then in
// E and S). D_PLAN and AXIS; code_aster has no plane stress version.
//
// Internal variables per Gauss point, as code_aster names them:
//   LEMAITRE: V1 EPSPEQ (p), V2 VIDE (0)
//   NORTON:   V1-V6 EPSPXX, EPSPYY, EPSPZZ, EPSPXY, EPSPXZ, EPSPYZ (the viscoplastic
//             strain, tensor components), V7 VIDE (0 by the theta scheme; the
//             cumulated p by Runge-Kutta, which integrates it)
//
// NORTON with ALGO_INTE='RUNGE_KUTTA' (code_aster's default) integrates instead the
// rates of y = (eps_v, p) explicitly, the strain varying linearly over the step, by
// Heun's method (second order) with an embedded first order error estimate and an
// adaptive sub-step, as code_aster (R5.03.14): the stress at (x, y) is Hooke's of
// eps_n + x/dt de - eps_v; from y and the rate a = y'(x, y), y1 = y + h a and
// y2 = y1 + h/2 (y'(x + h, y1) - a) with the error e = y2 - y1; the sub-step is
// accepted when max_i |e_i| / max(1e-4, |y_i(0)|) <= RESI_INTE_RELA (shear
// components as code_aster's, times sqrt 2), and the next h is h 0.9 w^(-1/5),
// w = max(error / RESI_INTE_RELA, 1e-5) (at most dt), or after a rejection
// w = min(error / RESI_INTE_RELA, 1e8). A rate below 1e-10 counts as none. Its
// tangent is the elastic one.
#pragma once
#include <string>
#include <vector>

#include "mechanics/behaviour_law.hpp"

namespace aster::mechanics {

enum class LemaitreVariables { Lemaitre, Norton };

struct LemaitreParameters {
  double young = 0, poisson = 0;
  double exponent = 1;     // N
  double inverseK = 0;     // UN_SUR_K (0: no flow)
  double inverseM = 0;     // UN_SUR_M (0: Norton)
  double theta = 1;        // PARM_THETA
  int maxIterations = 20;  // ITER_INTE_MAXI: the scalar equation's iterations
  double tolerance = 1e-6; // RESI_INTE_RELA: |F| below it ends them (in stress units, as code_aster);
                           // Runge-Kutta: the error accepted in a sub-step
  LemaitreVariables variables = LemaitreVariables::Lemaitre;
  bool rungeKutta = false;  // NORTON's ALGO_INTE='RUNGE_KUTTA' (else the theta scheme)
};

// The parameters of LEMAITRE and NORTON from DEFI_MATERIAU (ELAS's E, NU; LEMAITRE's
// N, UN_SUR_K, UN_SUR_M) and PARM_THETA, with code_aster's checks; they throw
// aster::Error naming the keyword (N > 0, UN_SUR_K >= 0, UN_SUR_M >= 0 and 0 for
// NORTON, PARM_THETA 0.5 or 1).
LemaitreParameters lemaitreParameters(double young, double poisson, double n, double inverseK, double inverseM,
                                      double theta);
LemaitreParameters nortonParameters(double young, double poisson, double n, double inverseK, double inverseM,
                                    double theta);

class LemaitreViscoplasticity final : public BehaviourLaw {
 public:
  // Throws aster::Error for parameters out of range and for C_PLAN.
  LemaitreViscoplasticity(LemaitreParameters parameters, PlaneHypothesis hypothesis);

  PlaneHypothesis hypothesis() const override { return hypothesis_; }
  int internalVariableCount() const override;
  std::vector<std::string> internalVariableNames() const override;
  bool predictsFromAcceptedState() const override { return true; }
  // Throws aster::Error when the scalar equation does not converge in ITER_INTE_MAXI
  // iterations or the time step is negative (the driver then cuts the step).
  void integrate(const LawInput& in, LawOutput<VoigtTangent>& out, bool withTangent) const override;

  const LemaitreParameters& parameters() const { return parameters_; }

 private:
  // The viscous rate g(x, p) = (x / K)^N p^(-N/M) and its partial derivatives.
  void rate(double x, double p, double& g, double& dgdx, double& dgdp) const;
  // NORTON by Runge-Kutta: the same outputs as integrate().
  void integrateRungeKutta(const LawInput& in, LawOutput<VoigtTangent>& out, bool withTangent) const;
  // code_aster's DEKKER: the root of the increasing F in ]0, q[ by regula falsi from
  // the bracket [0, q (1 - 1e-12)], the midpoint every third trial, until |F| < RESI_INTE_RELA.
  template <class Residual>
  double root(const Residual& F, double q) const;

  LemaitreParameters parameters_;
  PlaneHypothesis hypothesis_;
  double mu_, bulk_;
};

}  // namespace aster::mechanics
