// A behaviour law (code_aster's COMPORTEMENT/RELATION) at one Gauss point of a
// plane element: from the strain measure at the end of the increment, its
// increment, the stress and internal variables of the last accepted state and
// the law's own parameters, it computes the new stress, the new internal
// variables and the consistent tangent dS/dE. The element (plane_element.hpp)
// owns the kinematics: which strain measure (PETIT's eps or GROT_GDEP's
// Green-Lagrange E, modelling.hpp), its variation and the geometric stiffness.
// The law sees only the in-plane strain and the plane hypothesis it was built
// for (a C_PLAN law makes s_zz = 0 itself).
//
// A law is one class derived from BehaviourLaw; the element kernels run it
// through the virtual integrate() below. The element templates take the law as
// a parameter, so a final class with an inline integrate() can also be compiled
// into them: IsotropicElasticity (ELAS) is, AVX2 build included
// (element_kernel.cpp picks it, plane_element.cpp instantiates it).
#pragma once
#include <Eigen/Core>

namespace aster::mechanics {

// dS/dE in Voigt order: strains (E11, E22, 2 E12) -> stresses (S11, S22, S12).
// The element assembles one triangle of its matrix and mirrors it, so a law's
// tangent must be symmetric (hyperelastic, associated flow).
using VoigtTangent = Eigen::Matrix3d;

struct LawInput {
  Eigen::Matrix2d strain;           // eps (PETIT) or E (GROT_GDEP) at the end of the increment
  Eigen::Matrix2d strainIncrement;  // from the last accepted state
  const double* previousStress = nullptr;     // SIXX, SIYY, SIZZ, SIXY of the last accepted state
  const double* previousVariables = nullptr;  // internalVariableCount() values (V1, V2, ...)
};

template <class Tangent>
struct LawOutput {
  Eigen::Matrix2d stress;       // in-plane sigma (PETIT) or S (GROT_GDEP)
  double stressZZ = 0.0;        // the out-of-plane component
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
  // Internal variables per Gauss point (VARI_ELGA's V1, V2, ...).
  virtual int internalVariableCount() const = 0;
  // Throws aster::Error for a state the law cannot integrate (the step is then cut).
  virtual void integrate(const LawInput& in, LawOutput<VoigtTangent>& out, bool withTangent) const = 0;
};

}  // namespace aster::mechanics
