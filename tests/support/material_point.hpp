// One material point of a behaviour law and its accepted state, for the laws' unit
// tests: at() integrates a trial total strain (in-plane e, out-of-plane ezz) from the
// accepted state over dt, accept() makes a response the accepted state.
#pragma once
#include <vector>

#include <Eigen/Core>

#include "mechanics/behaviour_law.hpp"

namespace aster::test_support {

struct MaterialPoint {
  const mechanics::BehaviourLaw& law;
  Eigen::Matrix2d strain = Eigen::Matrix2d::Zero();
  double strainZZ = 0;
  double stress[4] = {0, 0, 0, 0};  // xx, yy, zz, xy
  std::vector<double> variables;
  explicit MaterialPoint(const mechanics::BehaviourLaw& l) : law(l), variables(l.internalVariableCount(), 0.0) {}

  mechanics::LawOutput<mechanics::VoigtTangent> at(const Eigen::Matrix2d& e, double ezz,
                                                   std::vector<double>& newVariables, double dt = 0.0,
                                                   bool withTangent = true) const {
    mechanics::LawInput in;
    in.strain = e;
    in.strainZZ = ezz;
    in.strainIncrement = e - strain;
    in.strainIncrementZZ = ezz - strainZZ;
    in.previousStress = stress;
    in.previousVariables = variables.data();
    in.timeIncrement = dt;
    mechanics::LawOutput<mechanics::VoigtTangent> out;
    newVariables.assign(variables.size(), 0.0);
    out.variables = newVariables.data();
    law.integrate(in, out, withTangent);
    return out;
  }
  void accept(const Eigen::Matrix2d& e, double ezz, const mechanics::LawOutput<mechanics::VoigtTangent>& out,
              const std::vector<double>& v) {
    strain = e;
    strainZZ = ezz;
    stress[0] = out.stress(0, 0);
    stress[1] = out.stress(1, 1);
    stress[2] = out.stressZZ;
    stress[3] = out.stress(0, 1);
    variables = v;
  }
};

}  // namespace aster::test_support
