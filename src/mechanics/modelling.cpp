#include "mechanics/modelling.hpp"

#include "core/error.hpp"

namespace aster::mechanics {

PlaneHypothesis planeHypothesisFromName(const std::string& word) {
  if (word == "D_PLAN") return PlaneHypothesis::PlaneStrain;
  if (word == "C_PLAN") return PlaneHypothesis::PlaneStress;
  if (word == "AXIS") return PlaneHypothesis::Axisymmetric;
  throw Error("MODELISATION must be 'D_PLAN', 'C_PLAN' or 'AXIS', got '" + word + "'");
}

const char* planeHypothesisName(PlaneHypothesis hypothesis) {
  switch (hypothesis) {
    case PlaneHypothesis::PlaneStrain: return "D_PLAN";
    case PlaneHypothesis::PlaneStress: return "C_PLAN";
    case PlaneHypothesis::Axisymmetric: return "AXIS";
  }
  return "?";
}

Kinematics kinematicsFromName(const std::string& word) {
  if (word == "PETIT") return Kinematics::SmallStrain;
  if (word == "GROT_GDEP" || word == "GREEN_LAGRANGE") return Kinematics::GreenLagrange;
  if (word == "GDEF_LOG") return Kinematics::Logarithmic;
  throw Error("DEFORMATION must be 'PETIT', 'GROT_GDEP', 'GREEN_LAGRANGE' or 'GDEF_LOG', got '" + word + "'");
}

}  // namespace aster::mechanics
