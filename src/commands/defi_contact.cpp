// DEFI_CONTACT: frictionless contact zones, DISCRETE or CONTINUE. The terms are
// built when STAT_NON_LINE numbers the unknowns (contact_concept.hpp).
#include "commands/contact_concept.hpp"
#include "commands/model_concepts.hpp"
#include "core/error.hpp"
#include "lang/operators.hpp"
#include "solver/contact_terms.hpp"

namespace aster::lang {
namespace {

ConceptPtr defiContact(const Keywords& k, Session&, ConceptPtr) {
  auto model = static_cast<ModelConcept&>(*k.conceptPtr("MODELE")).model;
  const auto& mesh = model->mesh();
  if (k.text("FROTTEMENT", "SANS") != "SANS")
    throw Error("FROTTEMENT='" + k.text("FROTTEMENT") + "': aster-lite's contact is frictionless (FROTTEMENT='SANS')");
  solver::ContactSettings settings;
  const std::string formulation = k.text("FORMULATION", "DISCRETE");
  settings.continueFormulation = formulation == "CONTINUE";
  std::vector<solver::ContactZone> zones;
  for (const auto& z : k.factor("ZONE")) {
    solver::ContactZone zone;
    zone.masterCells = mesh.cellGroup(z.text("GROUP_MA_MAIT"));
    zone.slaveCells = mesh.cellGroup(z.text("GROUP_MA_ESCL"));
    model->checkCellsOnModel(zone.masterCells, z.path + "/GROUP_MA_MAIT");
    model->checkCellsOnModel(zone.slaveCells, z.path + "/GROUP_MA_ESCL");
    if (z.has("TOLE_PROJ_EXT")) settings.outsideTolerance = z.real("TOLE_PROJ_EXT");
    if (settings.continueFormulation) {
      settings.rho = z.real("COEF_CONT", settings.rho);
      if (z.text("INTERPOL_LAGS_C", "LINEAIRE") == "QUADRATIQUE")
        settings.multipliers = contact::MultiplierInterpolation::Quadratic;
      const std::string integration = z.text("INTEGRATION", "AUTO");
      if (integration == "GAUSS") {
        settings.integration = contact::ContactIntegration::Gauss;
        settings.gaussPoints = static_cast<int>(z.integer("ORDRE_INT"));
      } else if (integration == "AUTO") {
        settings.integration = contact::ContactIntegration::Nodes;
      } else {
        throw Error(z.path + ": INTEGRATION='" + integration + "' is not available; use 'GAUSS' or 'AUTO'");
      }
    }
    zones.push_back(std::move(zone));
  }
  auto c = std::make_shared<ContactConcept>();
  c->formulation = formulation;
  c->makeTerms = [zones, settings](const solver::MechanicalSystem& system) {
    return solver::makeContactTerms(system, zones, settings);
  };
  return c;
}

RegisterOperator reg("DEFI_CONTACT", defiContact);

}  // namespace
}  // namespace aster::lang
