// DEFI_CONTACT (and DEFI_CONT, below): frictionless contact zones, DISCRETE or CONTINUE, each by exact
// constraints (CONTRAINTE / STANDARD) or penalisation. The terms are built when
// STAT_NON_LINE numbers the unknowns (contact_concept.hpp). Every keyword of the
// catalogue (commands/DEFI_CONTACT.lua) is read here or restricted there to the
// one value aster-lite implements.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "commands/contact_concept.hpp"
#include "commands/model_concepts.hpp"
#include "commands/selection.hpp"
#include "core/error.hpp"
#include "core/number_format.hpp"
#include "lang/operators.hpp"
#include "analysis/contact_terms.hpp"

namespace aster::lang {
namespace {

// A strictly positive coefficient of a zone, or a clear error naming it.
double positive(const Keywords& z, const std::string& key) {
  const double v = z.real(key);
  if (!(v > 0) || !std::isfinite(v)) {
    throw Error(z.path + "/" + key + " = " + format::significant(v, 6) + ": the coefficient must be > 0");
  }
  return v;
}

// Cells or nodes of the groups named by a keyword; an unknown group names the keyword.
template <class F>
auto ofGroups(const Keywords& z, const std::string& key, F&& lookup) {
  try {
    return lookup();
  } catch (const Error& e) {
    throw Error(z.path + "/" + key + ": " + e.what());
  }
}

// The part of a ZONE that DEFI_CONTACT and DEFI_CONT share: the master and
// slave cells (on the model, disjoint, oriented outwards when `checkNormals`)
// and the slave nodes without contact (SANS_GROUP_NO, SANS_NOEUD,
// SANS_GROUP_MA, SANS_MAILLE, those the zone's catalogue has).
analysis::ContactZone zoneSurfaces(const Keywords& z, const model::Model& model, bool checkNormals) {
  const auto& mesh = model.mesh();
  analysis::ContactZone zone;
  auto& zs = zone.settings;
  zone.masterCells = ofGroups(z, "GROUP_MA_MAIT", [&] { return mesh.cellGroup(z.text("GROUP_MA_MAIT")); });
  zone.slaveCells = ofGroups(z, "GROUP_MA_ESCL", [&] { return mesh.cellGroup(z.text("GROUP_MA_ESCL")); });
  model.checkCellsOnModel(zone.masterCells, z.path + "/GROUP_MA_MAIT");
  model.checkCellsOnModel(zone.slaveCells, z.path + "/GROUP_MA_ESCL");
  for (int c : zone.slaveCells)
    if (std::find(zone.masterCells.begin(), zone.masterCells.end(), c) != zone.masterCells.end())
      throw Error(z.path + ": cell " + mesh.cellName(c) + " is in both GROUP_MA_MAIT and GROUP_MA_ESCL");
  if (checkNormals)
    for (const std::string key : {"GROUP_MA_MAIT", "GROUP_MA_ESCL"}) {
      const auto [cell, inside] =
          analysis::inwardContactCell(mesh, key == "GROUP_MA_MAIT" ? zone.masterCells : zone.slaveCells);
      if (cell >= 0)
        throw Error(z.path + "/" + key + ": the normal of cell " + mesh.cellName(cell) + " (group '" + z.text(key) +
                    "') points into the cell " + mesh.cellName(inside) +
                    " it bounds; contact normals must point outwards: orient the group with "
                    "MODI_MAILLAGE/ORIE_PEAU, or give VERI_NORM='NON'");
    }
  // SANS_GROUP_NO, SANS_NOEUD, SANS_GROUP_MA, SANS_MAILLE: nodes without contact.
  for (const auto& g : z.has("SANS_GROUP_NO") ? z.texts("SANS_GROUP_NO") : std::vector<std::string>{})
    for (int n : ofGroups(z, "SANS_GROUP_NO", [&] { return mesh.nodeGroup(g); })) zs.excludedNodes.push_back(n);
  for (const auto& g : z.has("SANS_GROUP_MA") ? z.texts("SANS_GROUP_MA") : std::vector<std::string>{})
    for (int n : mesh.nodesOfCells(ofGroups(z, "SANS_GROUP_MA", [&] { return mesh.cellGroup(g); })))
      zs.excludedNodes.push_back(n);
  for (int n : namedNodes(mesh, z, "SANS_NOEUD")) zs.excludedNodes.push_back(n);
  for (int n : mesh.nodesOfCells(namedCells(mesh, z, "SANS_MAILLE"))) zs.excludedNodes.push_back(n);
  return zone;
}

// The model of a contact definition: plane (the contact terms are not weighted by the radius).
std::shared_ptr<const model::Model> contactModel(const Keywords& k) {
  auto model = static_cast<ModelConcept&>(*k.conceptPtr("MODELE")).model;
  if (model->axisymmetric())
    throw Error("the model is axisymmetric (MODELISATION='AXIS'), and aster-lite's contact terms "
                "are plane (not weighted by the radius): contact is available in D_PLAN and C_PLAN only");
  return model;
}

// CONTACT_INIT: the statuses of the first Newton iteration.
contact::ForcedStatus initialStatus(const Keywords& z) {
  const std::string init = z.text("CONTACT_INIT");
  return init == "OUI" ? contact::ForcedStatus::Contact
         : init == "NON" ? contact::ForcedStatus::Separated
                         : contact::ForcedStatus::None;
}

ConceptPtr contactConcept(std::vector<analysis::ContactZone> zones, const analysis::ContactSettings& settings) {
  auto c = std::make_shared<ContactConcept>();
  c->zones = std::move(zones);
  c->settings = settings;
  return c;
}

ConceptPtr defiContact(const Keywords& k, Session&, ConceptPtr) {
  const auto model = contactModel(k);
  const auto& mesh = model->mesh();
  if (k.text("FROTTEMENT") != "SANS")
    throw Error("FROTTEMENT='" + k.text("FROTTEMENT") + "': aster-lite's contact is frictionless (FROTTEMENT='SANS')");
  analysis::ContactSettings settings;
  settings.continueFormulation = k.text("FORMULATION") == "CONTINUE";
  settings.info = static_cast<int>(k.integer("INFO"));
  settings.smoothNormals = settings.continueFormulation && k.text("LISSAGE") == "OUI";
  const bool checkNormals = k.text("VERI_NORM") == "OUI";
  std::vector<analysis::ContactZone> zones;
  for (const auto& z : k.factor("ZONE")) {
    analysis::ContactZone zone = zoneSurfaces(z, *model, checkNormals);
    auto& zs = zone.settings;
    const std::string algo = z.text("ALGO_CONT");
    const bool lac = algo == "LAC";
    if (zones.empty()) settings.mortar = lac;
    if (lac != settings.mortar)
      throw Error(z.path + "/ALGO_CONT='" + algo + "': ALGO_CONT='LAC' must be given in every zone or in none");
    if (lac && settings.smoothNormals)
      throw Error("LISSAGE='OUI': ALGO_CONT='LAC' measures the gaps along the slave normals; give LISSAGE='NON'");
    if (!lac) {
      zs.outsideTolerance = z.real("TOLE_PROJ_EXT");
      if (!(zs.outsideTolerance >= 0))
        throw Error(z.path + "/TOLE_PROJ_EXT = " + std::to_string(zs.outsideTolerance) + ": it must be >= 0");
    }
    zs.maxDistance = z.real("DIST_APPA");
    if (lac) zs.lacPairs = z.text("ESPACE_LAGS_C") == "PAIRE";
    if (!settings.continueFormulation) {
      if (algo == "PENALISATION") zs.penalty = positive(z, "E_N");
    } else if (!lac) {
      if (algo == "PENALISATION") zs.penalty = positive(z, "COEF_PENA_CONT");
      else zs.rho = positive(z, "COEF_CONT");
      zs.multipliers = z.text("INTERPOL_LAGS_C") == "QUADRATIQUE"
                           ? contact::MultiplierInterpolation::Quadratic
                           : contact::MultiplierInterpolation::Linear;
      const std::string integration = z.text("INTEGRATION");
      if (integration == "GAUSS") {
        zs.integration = contact::ContactIntegration::Gauss;
        zs.gaussPoints = static_cast<int>(z.integer("ORDRE_INT"));
        const bool seg3 = std::any_of(zone.slaveCells.begin(), zone.slaveCells.end(),
                                      [&](int c) { return mesh.cellType(c) == mesh::CellType::SEG3; });
        if (zs.multipliers == contact::MultiplierInterpolation::Quadratic && seg3 && zs.gaussPoints < 3)
          throw Error(z.path + "/ORDRE_INT = " + std::to_string(zs.gaussPoints) +
                      ": INTERPOL_LAGS_C='QUADRATIQUE' on SEG3 slave cells needs ORDRE_INT >= 3");
      } else {
        zs.integration = contact::ContactIntegration::Nodes;  // 'AUTO', the validator allows nothing else
      }
    }
    if (settings.continueFormulation) zs.initialStatus = initialStatus(z);
    zones.push_back(std::move(zone));
  }
  return contactConcept(std::move(zones), settings);
}

// DEFI_CONT, code_aster's newer spelling of mortar contact: LAC's terms
// (mortar_contact.cpp) with COEF_CONT as the coefficient of the status
// criterion, LAGS_C + COEF_CONT x gap <= 0 (a pressure per unit gap, as given).
ConceptPtr defiCont(const Keywords& k, Session&, ConceptPtr) {
  const auto model = contactModel(k);
  analysis::ContactSettings settings;
  settings.continueFormulation = true;
  settings.mortar = true;
  settings.info = static_cast<int>(k.integer("INFO"));
  std::vector<analysis::ContactZone> zones;
  for (const auto& z : k.factor("ZONE")) {
    analysis::ContactZone zone = zoneSurfaces(z, *model, z.text("VERI_NORM") == "OUI");
    auto& zs = zone.settings;
    zs.maxDistance = z.real("DIST_APPA");
    zs.statusCoefficient = positive(z, "COEF_CONT");
    zs.initialStatus = initialStatus(z);
    zones.push_back(std::move(zone));
  }
  return contactConcept(std::move(zones), settings);
}

RegisterOperator reg("DEFI_CONTACT", defiContact);
RegisterOperator regCont("DEFI_CONT", defiCont);

}  // namespace
}  // namespace aster::lang
