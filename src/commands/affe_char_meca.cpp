// AFFE_CHAR_MECA (constant values), AFFE_CHAR_MECA_F (functions of X, Y, INST)
// and AFFE_CHAR_CINE (imposed displacements eliminated from the system).
#include <algorithm>

#include "commands/function_concepts.hpp"
#include "commands/model_concepts.hpp"
#include "commands/selection.hpp"
#include "core/error.hpp"
#include "lang/operators.hpp"
#include "mesh/orient.hpp"

namespace aster::lang {
namespace {

model::SpaceFunction valueOf(const Keywords& occ, const std::string& key) {
  if (!occ.has(key)) return model::SpaceFunction(0.0);
  const Value& v = occ.value(key);
  if (v.isNumber()) return model::SpaceFunction(v.real);
  try {
    return model::SpaceFunction(functionOf(v.concept));
  } catch (const Error& e) {
    throw Error(occ.path + "/" + key + ": " + e.what());
  }
}

void readImposed(const model::Model& m, const Keywords& occ, model::MechanicalLoad& load) {
  const auto nodes = selectNodes(m.mesh(), occ);
  for (int n : nodes)
    if (!m.nodeInModel(n))
      throw Error(occ.path + ": node " + m.mesh().nodeName(n) + " carries no element of the model, so no DX, DY");
  static const char* components[] = {"DX", "DY"};
  bool any = false;
  for (int c = 0; c < 2; ++c) {
    if (!occ.has(components[c])) continue;
    load.imposed.push_back({nodes, c, valueOf(occ, components[c])});
    any = true;
  }
  if (!any) throw Error(occ.path + ": give at least one of DX, DY");
}

// VERI_NORM='OUI': a pressure pushes against the normal of each edge, so an edge
// walked the wrong way round would pull instead. Every PRES_REP edge must have
// its normal out of the 2D cell it bounds, as code_aster checks.
void checkOutwardNormals(const mesh::Mesh& mesh, const Keywords& occ, const std::vector<int>& cells) {
  const auto inward = mesh::inwardSegments(mesh, cells);
  if (inward.empty()) return;
  const int s = inward.front().segment;
  std::string group;
  for (const auto& g : occ.texts("GROUP_MA")) {
    const auto& members = mesh.cellGroup(g);
    if (std::find(members.begin(), members.end(), s) != members.end()) {
      group = g;
      break;
    }
  }
  std::string groups;
  for (const auto& g : occ.texts("GROUP_MA")) groups += (groups.empty() ? "'" : ", '") + g + "'";
  throw Error(occ.path + "/GROUP_MA: the normal of cell " + mesh.cellName(s) + " (group " + group +
              ") points into the cell " + mesh.cellName(inward.front().cell) + " it bounds" +
              (inward.size() > 1 ? " (" + std::to_string(inward.size()) + " of the " + std::to_string(cells.size()) +
                                       " edges are reversed)"
                                 : std::string()) +
              ", so the pressure would pull; orient the edges first: MODI_MAILLAGE{reuse = <mesh>, MAILLAGE = <mesh>, "
              "ORIE_PEAU = {GROUP_MA_PEAU = {" + groups + "}}} (VERI_NORM = 'NON' skips this check)");
}

model::MechanicalLoad readMechanical(const model::Model& m, const Keywords& k) {
  model::MechanicalLoad load;
  const auto& mesh = m.mesh();
  for (const auto& occ : k.factor("DDL_IMPO")) readImposed(m, occ, load);
  for (const auto& occ : k.factor("FORCE_CONTOUR")) {
    const auto cells = selectCells(mesh, occ);
    for (int c : cells)
      if (mesh::topologicalDimension(mesh.cellType(c)) != 1)
        throw Error(occ.path + ": FORCE_CONTOUR applies to segments; cell " + mesh.cellName(c) + " is a " +
                    mesh::cellTypeName(mesh.cellType(c)));
    m.checkCellsOnModel(cells, occ.path);
    load.edgeForces.push_back({cells, valueOf(occ, "FX"), valueOf(occ, "FY")});
  }
  for (const auto& occ : k.factor("FORCE_INTERNE")) {
    std::vector<int> cells;
    for (int c : selectCells(mesh, occ))
      if (m.hasCell(c)) cells.push_back(c);
    if (cells.empty()) throw Error(occ.path + ": no cell of the model is selected");
    load.bodyForces.push_back({cells, valueOf(occ, "FX"), valueOf(occ, "FY")});
  }
  for (const auto& occ : k.factor("PRES_REP")) {
    const auto cells = selectCells(mesh, occ);
    for (int c : cells)
      if (mesh::topologicalDimension(mesh.cellType(c)) != 1)
        throw Error(occ.path + ": PRES_REP applies to segments in 2D; cell " + mesh.cellName(c) + " is a " +
                    mesh::cellTypeName(mesh.cellType(c)));
    m.checkCellsOnModel(cells, occ.path);
    if (k.text("VERI_NORM") == "OUI") checkOutwardNormals(mesh, occ, cells);
    load.pressures.push_back({cells, valueOf(occ, "PRES")});
  }
  for (const auto& occ : k.factor("FORCE_NODALE"))
    load.nodalForces.push_back({selectNodes(mesh, occ), valueOf(occ, "FX"), valueOf(occ, "FY")});
  return load;
}

ConceptPtr affeCharMeca(const Keywords& k, Session&, ConceptPtr) {
  auto m = static_cast<ModelConcept&>(*k.conceptPtr("MODELE")).model;
  return std::make_shared<LoadConcept>(m, readMechanical(*m, k));
}

ConceptPtr affeCharCine(const Keywords& k, Session&, ConceptPtr) {
  auto m = static_cast<ModelConcept&>(*k.conceptPtr("MODELE")).model;
  model::MechanicalLoad load;
  load.kinematic = true;
  for (const auto& occ : k.factor("MECA_IMPO")) readImposed(*m, occ, load);
  return std::make_shared<LoadConcept>(m, std::move(load));
}

RegisterOperator reg1("AFFE_CHAR_MECA", affeCharMeca);
RegisterOperator reg2("AFFE_CHAR_MECA_F", affeCharMeca);
RegisterOperator reg3("AFFE_CHAR_CINE", affeCharCine);

}  // namespace
}  // namespace aster::lang
