#include "mechanics/log_strain_law.hpp"

#include <cmath>

#include "core/error.hpp"
#include "mechanics/log_strain.hpp"

namespace aster::mechanics {

LogarithmicStrainLaw::LogarithmicStrainLaw(std::shared_ptr<const BehaviourLaw> law) : law_(std::move(law)) {
  if (!law_) throw Error("internal error: DEFORMATION='GDEF_LOG' without a behaviour law");
}

std::vector<std::string> LogarithmicStrainLaw::internalVariableNames() const {
  std::vector<std::string> names = law_->internalVariableNames();
  const int own = law_->internalVariableCount();
  if (static_cast<int>(names.size()) != own) {
    names.clear();
    for (int v = 1; v <= own; ++v) names.push_back("V" + std::to_string(v));
  }
  for (const char* name : {"TXX", "TYY", "TZZ", "TXY", "TXZ", "TYZ"}) names.emplace_back(name);
  return names;
}

void LogarithmicStrainLaw::integrate(const LawInput& in, LawOutput<VoigtTangent>& out, bool withTangent) const {
  const bool planeStress = hypothesis() == PlaneHypothesis::PlaneStress;
  const double Ezz = planeStress ? 0.0 : in.strainZZ;  // not given in C_PLAN (nor needed: see the header)
  const LogarithmicStrain current(in.strain, Ezz);
  const LogarithmicStrain previous(in.strain - in.strainIncrement, planeStress ? 0.0 : Ezz - in.strainIncrementZZ);

  const int own = law_->internalVariableCount();
  static constexpr double kNaturalState[kStressVariables] = {0, 0, 0, 0, 0, 0};
  LawInput inner;
  inner.strain = current.strain();
  inner.strainZZ = current.strainZZ();
  inner.strainIncrement = current.strain() - previous.strain();
  inner.strainIncrementZZ = current.strainZZ() - previous.strainZZ();
  inner.previousStress = in.previousVariables ? in.previousVariables + own : kNaturalState;  // TXX, TYY, TZZ, TXY
  inner.previousVariables = in.previousVariables;
  inner.time = in.time;
  inner.timeIncrement = in.timeIncrement;
  LawOutput<VoigtTangent> response;
  response.variables = out.variables;
  law_->integrate(inner, response, withTangent);

  const Eigen::Vector4d tau(response.stress(0, 0), response.stress(1, 1), response.stressZZ, response.stress(0, 1));
  if (out.variables) {
    double* t = out.variables + own;
    for (int i = 0; i < 4; ++i) t[i] = tau(i);
    t[4] = t[5] = 0.0;
  }
  const Eigen::Matrix4d P = current.projector();
  const Eigen::Vector4d S = P.transpose() * tau;
  out.stress << S(kXX), S(kXY), S(kXY), S(kYY);
  out.stressZZ = S(kZZ);
  out.strainZZ = planeStress ? 0.5 * std::expm1(2 * response.strainZZ) : Ezz;
  if (withTangent) out.tangent = P.transpose() * response.tangent * P + current.stressCurvature(tau);
}

}  // namespace aster::mechanics
