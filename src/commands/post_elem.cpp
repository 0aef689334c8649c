// POST_ELEM NORME: the L2 norm of a nodal field (or of a result's field at some
// instants) over the cells of the model or of groups; one row per group (and
// per instant) in a table with column VALE_NORM.
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

ConceptPtr postElem(const Keywords& k, Session& session, ConceptPtr) {
  const Keywords& occ = k.factor("NORME").at(0);
  std::shared_ptr<model::Model> model;
  if (occ.has("MODELE")) model = occ.concept<ModelConcept>("MODELE")->model;
  std::shared_ptr<ResultConcept> result;
  if (occ.has("RESULTAT")) {
    result = occ.concept<ResultConcept>("RESULTAT");
    if (!model) model = result->model;
  }
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
    cham = std::dynamic_pointer_cast<NodalFieldConcept>(c);
    if (!cham) throw Error("NORME: CHAM_GD " + session.nameOf(*c) + " is not a nodal field (cham_elem: not available yet)");
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
