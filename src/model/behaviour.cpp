#include "model/behaviour.hpp"

#include <algorithm>
#include <vector>

#include "core/error.hpp"
#include "core/number_format.hpp"
#include "mechanics/drucker_prager.hpp"
#include "mechanics/hyperelasticity.hpp"
#include "mechanics/isotropic_elasticity.hpp"
#include "mechanics/visc_endo_lemaitre.hpp"
#include "mechanics/lemaitre_viscoplasticity.hpp"
#include "mechanics/von_mises_plasticity.hpp"
#include "mechanics/visc_drucker_prager.hpp"

namespace aster::model {
namespace {

struct RelationRules {
  const char* name;
  std::vector<const char*> deformations;  // the DEFORMATION words it allows here
  bool axisymmetric;                      // AXIS allowed
  bool rateDependent = false;             // integrated in time: PARM_THETA applies
};

// The relations and what code_aster allows each of them (its Behaviours catalogue),
// less what aster-lite does not have.
const RelationRules* rulesOf(const std::string& relation) {
  static const std::vector<RelationRules> rules = {
      {"ELAS", {"PETIT", "GROT_GDEP", "GREEN_LAGRANGE", "GDEF_LOG"}, true},
      {"VMIS_ISOT_LINE", {"PETIT", "GROT_GDEP", "GDEF_LOG"}, true},
      {"VMIS_ISOT_TRAC", {"PETIT", "GROT_GDEP", "GDEF_LOG"}, true},
      {"VMIS_CINE_LINE", {"PETIT", "GROT_GDEP", "GDEF_LOG"}, true},
      {"VMIS_ECMI_LINE", {"PETIT", "GROT_GDEP", "GDEF_LOG"}, true},
      {"VMIS_ECMI_TRAC", {"PETIT", "GROT_GDEP", "GDEF_LOG"}, true},
      {"ELAS_HYPER", {"GROT_GDEP"}, false},
      {"VISC_DRUC_PRAG", {"PETIT"}, true, true},
      {"VISC_ENDO_LEMA", {"PETIT"}, true, true},
      {"DRUCK_PRAGER", {"PETIT", "GROT_GDEP"}, true},
      {"DRUCK_PRAG_N_A", {"PETIT", "GROT_GDEP"}, true},
      {"LEMAITRE", {"PETIT", "GROT_GDEP", "GDEF_LOG"}, true, true},
      {"NORTON", {"PETIT", "GDEF_LOG"}, true, true},
  };
  for (const auto& r : rules)
    if (relation == r.name) return &r;
  throw Error("COMPORTEMENT: unknown RELATION='" + relation + "'");
}

std::string words(const std::vector<const char*>& list) {
  std::string out;
  for (std::size_t i = 0; i < list.size(); ++i)
    out += std::string(i == 0 ? "" : i + 1 == list.size() ? " or " : ", ") + "'" + list[i] + "'";
  return out;
}

// ALGO_INTE: the integration code_aster allows for the relation, as aster-lite has it.
void checkAlgorithm(const std::string& relation, const std::string& algorithm) {
  if (algorithm.empty()) return;
  // code_aster's ALGO_INTE per relation (its Behaviours catalogue), the default first.
  static const std::map<std::string, std::vector<const char*>> algorithms = {
      {"NORTON", {"RUNGE_KUTTA", "NEWTON_PERT"}},
      {"LEMAITRE", {"DEKKER"}},
      {"VISC_ENDO_LEMA", {"SECANTE", "BRENT", "DEKKER"}},
      {"VISC_DRUC_PRAG", {"SECANTE", "BRENT"}},
  };
  const auto found = algorithms.find(relation);
  const std::vector<const char*> allowed = found != algorithms.end() ? found->second : std::vector<const char*>{"ANALYTIQUE"};
  if (std::find_if(allowed.begin(), allowed.end(), [&](const char* a) { return algorithm == a; }) == allowed.end())
    throw Error("RELATION='" + relation + "': ALGO_INTE='" + algorithm + "' is not available; this relation takes ALGO_INTE=" +
                words(allowed));
}

std::shared_ptr<const mechanics::BehaviourLaw> build(const std::string& relation, const BehaviourSite& site,
                                                     const IntegrationSettings& settings) {
  const ElasticMaterial& m = *site.material;
  auto needs = [&](bool present, const char* keyword) {
    if (!present)
      throw Error("RELATION='" + relation + "' needs " + keyword + " in DEFI_MATERIAU of material " +
                  site.materialName + " (cell " + site.cellName + ")");
  };
  const auto hypothesis = site.modelisation;
  if (relation == "ELAS_HYPER") {
    needs(m.hyper.has_value(), "ELAS_HYPER");
    const HyperelasticData& h = *m.hyper;
    const double bulk = h.bulkGiven ? h.bulk : mechanics::Hyperelasticity::bulkFromPoisson(h.c10, h.c01, h.poisson);
    return std::make_shared<mechanics::Hyperelasticity>(h.c10, h.c01, h.c20, bulk, hypothesis);
  }
  needs(m.hasElas, "ELAS");
  if (relation == "ELAS") return std::make_shared<mechanics::IsotropicElasticity>(m.E, m.NU, hypothesis);
  if (relation == "VISC_DRUC_PRAG") {
    needs(m.viscDrucPrag.has_value(), "VISC_DRUC_PRAG");
    mechanics::ViscDruckerPragerParameters v{m.E, m.NU, *m.viscDrucPrag, settings.maxIterations, settings.tolerance};
    return std::make_shared<mechanics::ViscDruckerPrager>(v, hypothesis);
  }
  if (relation == "VISC_ENDO_LEMA") {
    needs(m.lemaitre.has_value(), "LEMAITRE");
    needs(m.viscEndo.has_value(), "VISC_ENDO");
    auto p = mechanics::viscEndoLemaitreParameters(m.E, m.NU, m.lemaitre->n, m.lemaitre->unSurK, m.lemaitre->unSurM,
                                                   m.viscEndo->yield, m.viscEndo->rD, m.viscEndo->aD);
    p.maxIterations = settings.maxIterations;
    p.tolerance = settings.tolerance;
    return std::make_shared<mechanics::ViscEndoLemaitre>(p, hypothesis);
  }
  if (relation == "DRUCK_PRAGER" || relation == "DRUCK_PRAG_N_A") {
    needs(m.druckerPrager.has_value(), "DRUCK_PRAGER");
    const DruckerPragerData& d = *m.druckerPrager;
    mechanics::DruckerPragerParameters p;
    p.young = m.E;
    p.poisson = m.NU;
    p.alpha = d.alpha;
    p.yield = d.yield;
    p.ultimateStrain = d.ultimateStrain;
    p.hardening = d.parabolic ? mechanics::DruckerPragerParameters::Hardening::Parabolic
                              : mechanics::DruckerPragerParameters::Hardening::Linear;
    p.slope = d.slope;
    p.ultimateYield = d.ultimateYield;
    p.associated = relation == "DRUCK_PRAGER";
    p.dilatancy = d.dilatancy;
    return std::make_shared<mechanics::DruckerPrager>(p, hypothesis);
  }
  if (relation == "LEMAITRE" || relation == "NORTON") {
    needs(m.lemaitre.has_value(), "LEMAITRE");
    const LemaitreData& l = *m.lemaitre;
    auto lp = relation == "LEMAITRE"
                  ? mechanics::lemaitreParameters(m.E, m.NU, l.n, l.unSurK, l.unSurM, settings.theta)
                  : mechanics::nortonParameters(m.E, m.NU, l.n, l.unSurK, l.unSurM, settings.theta);
    lp.maxIterations = settings.maxIterations;
    lp.tolerance = settings.tolerance;
    lp.rungeKutta = relation == "NORTON" && settings.algorithm != "NEWTON_PERT";
    return std::make_shared<mechanics::LemaitreViscoplasticity>(lp, hypothesis);
  }
  mechanics::VonMisesParameters p;
  if (relation == "VMIS_ISOT_LINE") {
    needs(m.ecroLine.has_value(), "ECRO_LINE");
    p = mechanics::isotropicLinearParameters(m.E, m.NU, m.ecroLine->slope, m.ecroLine->yield);
  } else if (relation == "VMIS_CINE_LINE") {
    needs(m.ecroLine.has_value(), "ECRO_LINE");
    p = mechanics::kinematicLinearParameters(m.E, m.NU, m.ecroLine->slope, m.ecroLine->yield);
  } else if (relation == "VMIS_ECMI_LINE") {
    needs(m.ecroLine.has_value(), "ECRO_LINE");
    needs(m.prager.has_value(), "PRAGER");
    p = mechanics::mixedLinearParameters(m.E, m.NU, m.ecroLine->slope, m.ecroLine->yield, *m.prager);
  } else if (relation == "VMIS_ISOT_TRAC") {
    needs(m.traction.has_value(), "TRACTION");
    p = mechanics::isotropicTractionParameters(m.NU, *m.traction);
  } else {  // VMIS_ECMI_TRAC
    needs(m.traction.has_value(), "TRACTION");
    needs(m.prager.has_value(), "PRAGER");
    p = mechanics::mixedTractionParameters(m.NU, *m.traction, *m.prager);
  }
  p.maxIterations = settings.maxIterations;
  p.tolerance = settings.tolerance;
  return std::make_shared<mechanics::VonMisesPlasticity>(p, hypothesis);
}

}  // namespace

std::shared_ptr<const mechanics::BehaviourLaw> BehaviourFactory::law(const std::string& relation,
                                                                     const BehaviourSite& site,
                                                                     const IntegrationSettings& settings) {
  const RelationRules& rules = *rulesOf(relation);
  const auto& allowed = rules.deformations;
  if (std::find_if(allowed.begin(), allowed.end(), [&](const char* w) { return site.deformation == w; }) ==
      allowed.end())
    throw Error("RELATION='" + relation + "' (cell " + site.cellName + ") is not available with DEFORMATION='" +
                site.deformation + "': it takes DEFORMATION=" + words(allowed));
  if (!rules.axisymmetric && site.modelisation == mechanics::PlaneHypothesis::Axisymmetric)
    throw Error("RELATION='" + relation + "' (cell " + site.cellName +
                ") is not available in MODELISATION='AXIS' (code_aster allows it in 3D, D_PLAN and C_PLAN)");
  if (!rules.rateDependent && settings.theta != 1.0)
    throw Error("COMPORTEMENT: PARM_THETA=" + format::asterValue(settings.theta) + ": RELATION='" + relation +
                "' does not depend on time and is integrated by the implicit scheme alone (PARM_THETA=1)");
  checkAlgorithm(relation, settings.algorithm);
  // The integration settings matter to the laws with local iterations only; ELAS and ELAS_HYPER share one law.
  const bool iterates = relation != "ELAS" && relation != "ELAS_HYPER";
  const Key key{site.material, static_cast<int>(site.modelisation), relation, static_cast<int>(site.kinematics),
                iterates ? settings.maxIterations : 0, iterates ? settings.tolerance : 0.0, settings.theta,
                settings.algorithm};
  auto& slot = laws_[key];
  if (!slot) {
    try {
      slot = build(relation, site, settings);
    } catch (const Error& e) {
      laws_.erase(key);
      const std::string what = e.what();
      if (what.rfind("RELATION=", 0) == 0) throw;
      throw Error("RELATION='" + relation + "', material " + site.materialName + " (cell " + site.cellName +
                  "): " + what);
    }
  }
  return slot;
}

}  // namespace aster::model
