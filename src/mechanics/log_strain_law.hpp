// DEFORMATION='GDEF_LOG' (code_aster R5.03.24, after Miehe, Apel and Lambrecht
// 2002): a law written for small strains runs at finite strain on the logarithmic
// strain T = ln(C) / 2 and its dual stress tau (log_strain.hpp). This class wraps
// the law as a law of the Green-Lagrange strain E, so that the element runs
// GDEF_LOG as it runs GROT_GDEP (total Lagrangian, S and the geometric stiffness):
//  - T and the previous T_n from E and E_n = E - dE (the element recomputes E_n
//    from the previous displacement), the law integrated from (T_n, tau_n) to
//    (T, tau) with its own internal variables;
//  - S = tau : P with P = dT/dE, and dS/dE = P^T D P + tau : d2T/dE2 (exact;
//    symmetric when the law's tangent D is).
// Internal variables: the law's, then the 6 GDEF_LOG adds in code_aster, TXX, TYY,
// TZZ, TXY, TXZ, TYZ, the stress tau (TXZ = TYZ = 0 in the plane): the law's
// previous stress, as the element's history keeps S (and SIEF_ELGA the Cauchy
// stress F S F^T / J).
// Every hypothesis of the law: zz is a principal direction of C, so P does not
// couple zz with the plane and, in C_PLAN, S_zz = 0 exactly when tau_zz = 0: the
// law's condensation on tau_zz = 0 is the condensation on S_zz = 0, and its T_zz
// gives E_zz = (exp(2 T_zz) - 1) / 2, which this law reports.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "mechanics/behaviour_law.hpp"

namespace aster::mechanics {

class LogarithmicStrainLaw final : public BehaviourLaw {
 public:
  static constexpr int kStressVariables = 6;  // TXX, TYY, TZZ, TXY, TXZ, TYZ

  // Throws aster::Error without a law.
  explicit LogarithmicStrainLaw(std::shared_ptr<const BehaviourLaw> law);

  const BehaviourLaw& law() const { return *law_; }
  PlaneHypothesis hypothesis() const override { return law_->hypothesis(); }
  int internalVariableCount() const override { return law_->internalVariableCount() + kStressVariables; }
  // The law's names (V1, V2, ... where it gives none), then TXX, TYY, TZZ, TXY, TXZ, TYZ.
  std::vector<std::string> internalVariableNames() const override;
  bool symmetricTangent() const override { return law_->symmetricTangent(); }
  bool predictsFromAcceptedState() const override { return law_->predictsFromAcceptedState(); }
  // in.strain: E; out.stress: S; out.tangent: dS/dE.
  void integrate(const LawInput& in, LawOutput<VoigtTangent>& out, bool withTangent) const override;

 private:
  std::shared_ptr<const BehaviourLaw> law_;
};

}  // namespace aster::mechanics
