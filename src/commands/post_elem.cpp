// POST_ELEM NORME: the L2 norm of a nodal field (or of a result's field at some
// instants) over the cells of the model or of groups; one row per group (and
// per instant) in a table with column VALE_NORM. A field at Gauss points
// (cham_elem, ELGA_*) is integrated at its points, those of the model's
// integration scheme: sqrt(sum over cells and points of w_q |J_q| sum_c coef_c v_c^2).
#include <algorithm>
#include <cmath>

#include "commands/elga_field.hpp"
#include "commands/field_concepts.hpp"
#include "commands/model_concepts.hpp"
#include "commands/table_concept.hpp"
#include "core/error.hpp"
#include "lang/operators.hpp"
#include "post/norms.hpp"

namespace aster::lang {
namespace {

struct Part {
  std::string name;
  std::vector<int> cells;
};

void checkSupport(const mesh::Mesh& mesh, const std::vector<int>& support, const std::vector<int>& cells,
                  const std::string& what) {
  if (support.empty()) return;
  std::vector<char> in(mesh.nodeCount(), 0);
  for (int n : support) in[n] = 1;
  for (int c : cells)
    for (int n : mesh.cellNodes(c))
      if (!in[n])
        throw Error(what + " is not defined at node " + mesh.nodeName(n) + " of cell " + mesh.cellName(c));
}

// The L2 norm of a field at Gauss points over `cells`.
double elgaNorm(const model::Model& model, const CellFieldConcept& f, const std::vector<int>& cells,
                const std::vector<int>& comps, const std::vector<double>& weights, const std::string& what,
                const std::string& part) {
  const auto& mesh = model.mesh();
  std::vector<int> position(mesh.cellCount(), -1);
  for (std::size_t k = 0; k < f.field.cells.size(); ++k) position[f.field.cells[k]] = static_cast<int>(k);
  const std::size_t nc = f.field.components.size();
  double sum = 0;
  int dim = -1;
  for (int cell : cells) {
    const int k = position[cell];
    if (k < 0)
      throw Error("NORME: the field " + what + " is not defined on cell " + mesh.cellName(cell) + " of " + part);
    for (int c : comps)
      if (!componentPresent(f, static_cast<std::size_t>(k), static_cast<std::size_t>(c)))
        throw Error("NORME: component " + f.field.components[c] + " of the field " + what +
                    " is not defined on cell " + mesh.cellName(cell) + " of " + part +
                    " (NOM_CMP chooses the components; CREA_CHAMP's PROL_ZERO='OUI' makes missing ones zero)");
    const post::CellGaussPoints g = post::modelGaussPoints(mesh, cell, model.axisymmetric());
    if (dim >= 0 && g.dimension != dim)
      throw Error("NORME: " + part + " mixes surface and edge cells (cell " + mesh.cellName(cell) +
                  "); integrate surfaces and edges separately");
    dim = g.dimension;
    if (pointsOf(f.field, static_cast<std::size_t>(k)) != g.count)
      throw Error("NORME: the field " + what + " has " + std::to_string(pointsOf(f.field, static_cast<std::size_t>(k))) +
                  " points on cell " + mesh.cellName(cell) + "; the model integrates it with " + std::to_string(g.count));
    const double* v = f.field.values.data() + f.field.offsets[k];
    for (int q = 0; q < g.count; ++q)
      for (std::size_t i = 0; i < comps.size(); ++i) {
        const double x = v[q * nc + comps[i]];
        sum += g.weights[q] * (weights.empty() ? 1.0 : weights[i]) * x * x;
      }
  }
  if (cells.empty()) throw Error("NORME: no cell to integrate over in " + part);
  return std::sqrt(sum);
}

// NORME of a field at Gauss points: one row per group.
ConceptPtr elgaNorms(const Keywords& k, const Keywords& occ, const CellFieldConcept& f, const model::Model& model,
                     const std::vector<Part>& parts, const std::string& what) {
  if (f.mesh.get() != &model.mesh()) throw Error("NORME: CHAM_GD lies on another mesh than the model");
  if (const auto* e = dynamic_cast<const ElgaFieldConcept*>(&f); e && e->functionField)
    throw Error("NORME: CHAM_GD " + what + " is a field of functions; evaluate it first (CREA_CHAMP OPERATION='EVAL')");
  std::vector<std::string> names;
  if (occ.has("NOM_CMP")) {
    names = occ.texts("NOM_CMP");
  } else {
    for (const auto& c : f.field.components)
      if (c.rfind("LAGS", 0) != 0) names.push_back(c);
  }
  std::vector<int> comps;
  for (const auto& n : names) {
    auto it = std::find(f.field.components.begin(), f.field.components.end(), n);
    if (it == f.field.components.end()) {
      std::string list;
      for (const auto& c : f.field.components) list += (list.empty() ? "" : ", ") + c;
      throw Error("NORME: NOM_CMP: the field " + what + " has no component " + n + " (components: " + list + ")");
    }
    comps.push_back(static_cast<int>(it - f.field.components.begin()));
  }
  std::vector<double> weights;
  if (occ.has("COEF_MULT")) {
    weights = occ.reals("COEF_MULT");
    if (weights.size() != names.size())
      throw Error("NORME: COEF_MULT has " + std::to_string(weights.size()) + " value(s) for " +
                  std::to_string(names.size()) + " component(s)");
  }
  std::string cmpList;
  for (const auto& n : names) cmpList += (cmpList.empty() ? "" : " ") + n;
  post::Table table;
  for (const auto& part : parts) {
    const double norm = elgaNorm(model, f, part.cells, comps, weights, what,
                                 part.name == "TOUT" ? std::string("the model") : "GROUP_MA " + part.name);
    table.addRow({{"GROUP_MA", post::TableValue::ofText(part.name)},
                  {"NOM_CMP", post::TableValue::ofText(cmpList)},
                  {"TYPE_NORM", post::TableValue::ofText("L2")},
                  {"VALE_NORM", post::TableValue::ofReal(norm)}});
  }
  if (k.has("TITRE")) table.titles = k.texts("TITRE");
  return std::make_shared<TableConcept>(table);
}

ConceptPtr postElem(const Keywords& k, Session& session, ConceptPtr) {
  const Keywords& occ = k.factor("NORME").at(0);
  std::shared_ptr<model::Model> model;
  if (occ.has("MODELE")) model = occ.concept<ModelConcept>("MODELE")->model;
  std::shared_ptr<ResultConcept> result;
  if (occ.has("RESULTAT")) {
    result = occ.concept<ResultConcept>("RESULTAT");
    if (!model) model = result->model;
  }
  if (model->axisymmetric())
    throw Error("NORME: the model is axisymmetric (MODELISATION='AXIS'); aster-lite integrates the norms "
                "over the plane section only, not per radian: NORME is available in D_PLAN and C_PLAN");
  const mesh::Mesh& mesh = model->mesh();
  std::vector<Part> parts;
  if (occ.has("TOUT")) {
    parts.push_back({"TOUT", model->cells()});
  } else {
    for (const auto& g : occ.texts("GROUP_MA")) parts.push_back({g, mesh.cellGroup(g)});
  }
  // (NUME_ORDRE, INST, field) to integrate.
  struct Item {
    int index = -1;
    double time = 0;
    const mesh::NodalField* field;
    std::vector<int> support;
    std::string what;
  };
  std::vector<Item> items;
  std::shared_ptr<NodalFieldConcept> cham;
  if (occ.has("CHAM_GD")) {
    const auto c = occ.conceptPtr("CHAM_GD");
    if (const auto g = std::dynamic_pointer_cast<CellFieldConcept>(c))
      return elgaNorms(k, occ, *g, *model, parts, session.nameOf(*c));
    cham = std::dynamic_pointer_cast<NodalFieldConcept>(c);
    if (!cham) throw Error("NORME: CHAM_GD " + session.nameOf(*c) + " is not a field");
    if (isFunctionField(*cham)) throw Error("NORME: CHAM_GD " + session.nameOf(*c) + " is a field of functions; evaluate it first");
    if (cham->mesh.get() != &mesh) throw Error("NORME: CHAM_GD lies on another mesh than the model");
    items.push_back({-1, 0, &cham->field, cham->support, session.nameOf(*c)});
  } else {
    const std::string name = occ.text("NOM_CHAM");
    std::vector<const ResultInstant*> chosen;
    if (occ.has("INST")) {
      for (double t : occ.reals("INST")) chosen.push_back(&result->at(t));
    } else if (occ.has("NUME_ORDRE")) {
      for (const auto& v : occ.values("NUME_ORDRE")) {
        Keywords one;
        one.setSimple("NUME_ORDRE", {v});
        chosen.push_back(&instantOf(*result, one));
      }
    } else {
      for (const auto& i : result->instants) chosen.push_back(&i);
    }
    for (const auto* i : chosen)
      items.push_back({i->index, i->time, &ResultConcept::nodalField(*i, name), {}, name});
  }
  post::Table table;
  for (const auto& item : items) {
    post::NodalValues nv;
    nv.values = &item.field->values;
    nv.componentCount = static_cast<int>(item.field->components.size());
    std::vector<std::string> names;
    if (occ.has("NOM_CMP")) {
      names = occ.texts("NOM_CMP");
    } else {
      // Every component but the Lagrange multipliers (LAGS_C lives on contact nodes only).
      for (const auto& c : item.field->components)
        if (c.rfind("LAGS", 0) != 0) names.push_back(c);
    }
    for (const auto& n : names) nv.components.push_back(componentIndex(*item.field, n, item.what));
    if (occ.has("COEF_MULT")) {
      nv.weights = occ.reals("COEF_MULT");
      if (nv.weights.size() != names.size())
        throw Error("NORME: COEF_MULT has " + std::to_string(nv.weights.size()) + " value(s) for " +
                    std::to_string(names.size()) + " component(s)");
    }
    std::string cmpList;
    for (const auto& n : names) cmpList += (cmpList.empty() ? "" : " ") + n;
    for (const auto& part : parts) {
      checkSupport(mesh, item.support, part.cells, item.what);
      const auto r = post::l2Norms(mesh, part.cells, nv);
      std::vector<std::pair<std::string, post::TableValue>> row;
      if (item.index >= 0) {
        row.push_back({"NUME_ORDRE", post::TableValue::ofInteger(item.index)});
        row.push_back({"INST", post::TableValue::ofReal(item.time)});
      }
      row.push_back({"GROUP_MA", post::TableValue::ofText(part.name)});
      row.push_back({"NOM_CMP", post::TableValue::ofText(cmpList)});
      row.push_back({"TYPE_NORM", post::TableValue::ofText("L2")});
      row.push_back({"VALE_NORM", post::TableValue::ofReal(r.computed)});
      table.addRow(row);
    }
  }
  if (k.has("TITRE")) table.titles = k.texts("TITRE");
  return std::make_shared<TableConcept>(table);
}

RegisterOperator reg("POST_ELEM", postElem);

}  // namespace
}  // namespace aster::lang
