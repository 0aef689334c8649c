// A behaviour law (code_aster's COMPORTEMENT/RELATION) at one Gauss point of a
// plane or axisymmetric element: from the strain measure at the end of the
// increment, its increment, the stress and internal variables of the last
// accepted state and the law's own parameters, it computes the new stress, the
// new internal variables and the consistent tangent dS/dE. The element
// (plane_element.hpp) owns the kinematics: which strain measure (PETIT's eps or
// GROT_GDEP's Green-Lagrange E, modelling.hpp), its variation and the geometric
// stiffness. Under GDEF_LOG the law sees the logarithmic strain T and returns its
// dual stress, LogarithmicStrainLaw (log_strain_law.hpp) mapping both to E and S.
//
// Strains and stresses have four components, xx, yy, zz, xy (zz the
// out-of-plane direction: the thickness in D_PLAN/C_PLAN, the hoop direction in
// AXIS), so that a 3D law (plasticity) sees the whole state:
//  - D_PLAN: the element gives strainZZ = 0; the law returns stressZZ and the
//    full 4x4 tangent (the element uses its in-plane part).
//  - AXIS: the element gives the hoop strain (u_r/r, or E_tt = (F_tt^2 - 1)/2);
//    the element uses the full 4x4 tangent.
//  - C_PLAN: strainZZ is unknown to the element (given as 0, not to be read);
//    the law finds it from s_zz = 0 itself, returns stressZZ = 0 and the tangent
//    condensed on s_zz = 0 (its zz row and column zero), and may report the zz
//    strain it found in strainZZ.
// A law is built for one hypothesis (IsotropicElasticity takes it).
//
// A law is one class derived from BehaviourLaw; the element kernels run it
// through the virtual integrate() below. The element templates take the law as
// a parameter, so a final class with an inline integrate() can also be compiled
// into them: IsotropicElasticity (ELAS) is, AVX2 build included, for D_PLAN and
// C_PLAN (element_kernel.cpp picks it, plane_element.cpp instantiates it); AXIS
// elements call the law's 4-component integrate().
#pragma once
#include <string>
#include <vector>

#include <Eigen/Core>

#include "mechanics/modelling.hpp"

namespace aster::mechanics {

// dS/dE in Voigt order: strains (E11, E22, E33, 2 E12) -> stresses (S11, S22,
// S33, S12), 3 the out-of-plane direction. For a law whose tangent is symmetric
// (hyperelastic, associated flow) the element assembles one triangle of its matrix
// and mirrors it; a law says otherwise through symmetricTangent() (non-associated
// flow), and the element then assembles the whole matrix.
using VoigtTangent = Eigen::Matrix4d;
// Voigt indices.
enum VoigtIndex { kXX = 0, kYY = 1, kZZ = 2, kXY = 3 };

struct LawInput {
  Eigen::Matrix2d strain;           // eps (PETIT), E (GROT_GDEP) or T (GDEF_LOG) at the end of the increment
  double strainZZ = 0.0;            // out of plane: 0 (D_PLAN), hoop (AXIS), not given (C_PLAN)
  Eigen::Matrix2d strainIncrement;  // from the last accepted state
  double strainIncrementZZ = 0.0;
  const double* previousStress = nullptr;     // SIXX, SIYY, SIZZ, SIXY of the last accepted state
  const double* previousVariables = nullptr;  // internalVariableCount() values (V1, V2, ...)
  double time = 0.0;           // INST at the end of the increment
  double timeIncrement = 0.0;  // its length (0 when the state is the accepted one)
};

template <class Tangent>
struct LawOutput {
  Eigen::Matrix2d stress;       // in-plane sigma (PETIT), S (GROT_GDEP) or T's dual (GDEF_LOG)
  double stressZZ = 0.0;        // the out-of-plane component (0 in C_PLAN)
  double strainZZ = 0.0;        // C_PLAN: the out-of-plane strain making s_zz = 0, when the law reports it
  double* variables = nullptr;  // internalVariableCount() values, written by the law
  Tangent tangent;              // written when asked for
};

class BehaviourLaw {
 public:
  using Tangent = VoigtTangent;
  // Whether integrate() reads the increment, the previous stress and variables
  // (the element then gathers them); a law without history need not.
  static constexpr bool kUsesHistory = true;

  virtual ~BehaviourLaw();
  // The hypothesis the law was built for: the element's formulation (AXIS) follows it.
  virtual PlaneHypothesis hypothesis() const = 0;
  // Internal variables per Gauss point (VARI_ELGA's V1, V2, ...).
  virtual int internalVariableCount() const = 0;
  // Their names (code_aster's NOM_VARI: EPSPEQ, INDIPLAS, ...), internalVariableCount() of them.
  virtual std::vector<std::string> internalVariableNames() const { return {}; }
  // Whether the tangent is symmetric whatever the state (false: non-associated flow).
  virtual bool symmetricTangent() const { return true; }
  // Whether a step's prediction balances the internal forces of the accepted state rather
  // than those of the law integrated over the step at the same displacement, which differ
  // for a law whose stress moves with time at an unchanged strain (the viscous laws): as
  // code_aster's prediction (RIGI_MECA_TANG) does; ssnp02a-c meet its values to 3e-9 so,
  // to 3e-5 otherwise. Convergence is never declared on this residual.
  virtual bool predictsFromAcceptedState() const { return false; }
  // Throws aster::Error for a state the law cannot integrate (the step is then cut).
  virtual void integrate(const LawInput& in, LawOutput<VoigtTangent>& out, bool withTangent) const = 0;
};

}  // namespace aster::mechanics
