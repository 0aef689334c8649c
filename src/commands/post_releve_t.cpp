// POST_RELEVE_T ACTION OPERATION='EXTRACTION': field values at nodes (GROUP_NO
// in the group's order, NOEUD, or TOUT) into a table: INTITULE, NOEUD,
// NUME_ORDRE and INST (from a result), COOR_X, COOR_Y, ABSC_CURV (distance along
// the listed nodes), then one column per component.
#include <cmath>

#include "commands/field_concepts.hpp"
#include "commands/table_concept.hpp"
#include "core/error.hpp"
#include "core/messages.hpp"
#include "lang/operators.hpp"

namespace aster::lang {
namespace {

ConceptPtr postReleveT(const Keywords& k, Session& session, ConceptPtr reuse) {
  post::Table table;
  if (reuse) table = static_cast<TableConcept&>(*reuse).table;
  for (const auto& occ : k.factor("ACTION")) {
    struct Item {
      const mesh::NodalField* field;
      std::vector<int> support;
      int index = -1;
      double time = 0;
    };
    std::vector<Item> items;
    std::shared_ptr<const mesh::Mesh> mesh;
    std::string what;
    if (occ.has("CHAM_GD")) {
      const auto c = occ.conceptPtr("CHAM_GD");
      auto f = std::dynamic_pointer_cast<NodalFieldConcept>(c);
      if (!f || isFunctionField(*f)) throw Error(occ.path + ": CHAM_GD " + session.nameOf(*c) + " is not a field of real nodal values");
      items.push_back({&f->field, f->support});
      mesh = f->mesh;
      what = session.nameOf(*c);
    } else {
      const auto r = occ.concept<ResultConcept>("RESULTAT");
      mesh = r->model->meshPtr();
      what = occ.text("NOM_CHAM");
      std::vector<const ResultInstant*> chosen;
      if (occ.has("INST")) {
        Keywords one;
        one.setSimple("CRITERE", {Value::ofText(occ.text("CRITERE"))});
        one.setSimple("PRECISION", {Value::ofReal(occ.real("PRECISION"))});
        for (double t : occ.reals("INST")) {
          one.setSimple("INST", {Value::ofReal(t)});
          chosen.push_back(&instantOf(*r, one));
        }
      } else if (occ.has("NUME_ORDRE")) {
        for (const auto& v : occ.values("NUME_ORDRE")) {
          Keywords n;
          n.setSimple("NUME_ORDRE", {v});
          chosen.push_back(&instantOf(*r, n));
        }
      } else if (occ.has("LIST_INST")) {
        throw Error(occ.path + ": LIST_INST is not available yet; give INST");
      } else {
        for (const auto& i : r->instants) chosen.push_back(&i);
      }
      for (const auto* i : chosen) items.push_back({&ResultConcept::nodalField(*i, what), {}, i->index, i->time});
    }
    std::vector<int> nodes;
    if (occ.has("GROUP_NO")) {
      for (const auto& g : occ.texts("GROUP_NO"))
        for (int n : mesh->nodeGroup(g)) nodes.push_back(n);
    } else if (occ.has("NOEUD")) {
      for (const auto& n : occ.texts("NOEUD")) nodes.push_back(mesh->nodeIndex(n));
    }
    for (const auto& item : items) {
      std::vector<int> listed = nodes;
      if (occ.has("TOUT")) {
        listed = item.support;
        if (listed.empty())
          for (int n = 0; n < mesh->nodeCount(); ++n) listed.push_back(n);
      }
      std::vector<char> in(mesh->nodeCount(), item.support.empty() ? 1 : 0);
      for (int n : item.support) in[n] = 1;
      const auto& f = *item.field;
      std::vector<std::string> cmps = occ.has("NOM_CMP") ? occ.texts("NOM_CMP") : f.components;
      std::vector<int> ci;
      for (const auto& c : cmps) ci.push_back(componentIndex(f, c, what));
      double absc = 0;
      for (std::size_t i = 0; i < listed.size(); ++i) {
        const int n = listed[i];
        if (!in[n]) throw Error(occ.path + ": the field " + what + " is not defined at node " + mesh->nodeName(n));
        if (i > 0) absc += (mesh->node(n) - mesh->node(listed[i - 1])).norm();
        std::vector<std::pair<std::string, post::TableValue>> row{
            {"INTITULE", post::TableValue::ofText(occ.text("INTITULE"))},
            {"NOEUD", post::TableValue::ofText(mesh->nodeName(n))}};
        if (item.index >= 0) {
          row.push_back({"NUME_ORDRE", post::TableValue::ofInteger(item.index)});
          row.push_back({"INST", post::TableValue::ofReal(item.time)});
        }
        row.push_back({"ABSC_CURV", post::TableValue::ofReal(absc)});
        row.push_back({"COOR_X", post::TableValue::ofReal(mesh->node(n)(0))});
        row.push_back({"COOR_Y", post::TableValue::ofReal(mesh->node(n)(1))});
        for (std::size_t c = 0; c < cmps.size(); ++c)
          row.push_back({cmps[c], post::TableValue::ofReal(f.values[n * f.components.size() + ci[c]])});
        table.addRow(row);
      }
    }
  }
  if (k.has("TITRE")) table.titles = k.texts("TITRE");
  if (k.integer("INFO") >= 2) Messages::info(table.formatTableau());
  if (reuse) {
    static_cast<TableConcept&>(*reuse).table = table;
    return reuse;
  }
  return std::make_shared<TableConcept>(table);
}

RegisterOperator reg("POST_RELEVE_T", postReleveT);

}  // namespace
}  // namespace aster::lang
