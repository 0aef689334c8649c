// COMPORTEMENT's RELATION: the behaviour law of a cell from the relation's name,
// the cell's material (DEFI_MATERIAU's keywords), its modelisation and its
// DEFORMATION, with code_aster's rules on which of these each relation accepts.
// One law object per (material, modelisation, relation, kinematics, integration
// settings), so that the cells sharing them share the law (and the element kernels
// built on it: analysis::MechanicalSystem caches kernels by law).
#pragma once
#include <map>
#include <memory>
#include <string>
#include <tuple>

#include "mechanics/behaviour_law.hpp"
#include "mechanics/modelling.hpp"
#include "model/material.hpp"

namespace aster::model {

// COMPORTEMENT's ITER_INTE_MAXI and RESI_INTE_RELA (the laws' local iterations) and
// PARM_THETA (the time integration of the rate-dependent laws), ALGO_INTE.
struct IntegrationSettings {
  int maxIterations = 20;
  double tolerance = 1e-6;
  double theta = 1.0;
  std::string algorithm;  // ALGO_INTE, "" when not given (the relation's default)
};

// What a relation is applied to: the cell (for messages) and its data.
struct BehaviourSite {
  const ElasticMaterial* material = nullptr;
  std::string materialName;  // the material's concept name, for messages
  std::string cellName;
  mechanics::PlaneHypothesis modelisation = mechanics::PlaneHypothesis::PlaneStrain;
  std::string deformation = "PETIT";  // COMPORTEMENT's DEFORMATION word
  mechanics::Kinematics kinematics = mechanics::Kinematics::SmallStrain;
};

class BehaviourFactory {
 public:
  // The law of `relation` (ELAS, VMIS_ISOT_LINE, VMIS_ISOT_TRAC, VMIS_CINE_LINE,
  // VMIS_ECMI_LINE, VMIS_ECMI_TRAC, ELAS_HYPER, VISC_DRUC_PRAG, VISC_ENDO_LEMA, DRUCK_PRAGER,
  // DRUCK_PRAG_N_A, LEMAITRE, NORTON) at `site`. Throws aster::Error naming
  // the relation, the material and the cell when the material lacks a keyword the
  // relation needs, or the DEFORMATION or the modelisation is not one it allows.
  std::shared_ptr<const mechanics::BehaviourLaw> law(const std::string& relation, const BehaviourSite& site,
                                                     const IntegrationSettings& settings);

 private:
  using Key = std::tuple<const ElasticMaterial*, int, std::string, int, int, double, double, std::string>;
  std::map<Key, std::shared_ptr<const mechanics::BehaviourLaw>> laws_;
};

}  // namespace aster::model
