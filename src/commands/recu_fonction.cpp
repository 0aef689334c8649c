// RECU_FONCTION: a tabulated function (fonction_sdaster) from two columns of a
// table, after FILTRE, or from a result: one component of a field at one place
// (a node of a nodal field; a Gauss point, POINT, of a cell of a field at Gauss
// points; a node of a cell of a field at cell nodes) over the instants chosen
// (every one by default), as a function of INST named after the component (as
// code_aster: LIN LIN, EXCLU on both sides unless INTERPOL / PROL_* say otherwise).
#include <algorithm>
#include <numeric>

#include "commands/field_concepts.hpp"
#include "commands/function_concepts.hpp"
#include "commands/instant_selection.hpp"
#include "commands/selection.hpp"
#include "core/number_format.hpp"
#include "commands/table_concept.hpp"
#include "core/error.hpp"
#include "core/messages.hpp"
#include "expr/tabulated.hpp"
#include "lang/operators.hpp"

namespace aster::lang {
namespace {

// The one node or cell a keyword designates: NOEUD / MAILLE, else the group's
// first (an alarm when the group has several, as code_aster).
int oneOf(const Keywords& k, const mesh::Mesh& mesh, bool node) {
  const std::string single = node ? "NOEUD" : "MAILLE", group = node ? "GROUP_NO" : "GROUP_MA";
  if (k.has(single))
    return node ? namedNode(mesh, k, single, k.text(single)) : namedCell(mesh, k, single, k.text(single));
  const std::string name = k.text(group);
  const auto& members = node ? mesh.nodeGroup(name) : mesh.cellGroup(name);
  if (members.empty()) throw Error(group + " " + name + " is empty");
  if (members.size() > 1)
    Messages::alarm("RECU_FONCTION", group + " " + name + " has " + std::to_string(members.size()) + " " +
                                         (node ? "nodes" : "cells") + "; the first, " +
                                         (node ? mesh.nodeName(members[0]) : mesh.cellName(members[0])) +
                                         ", is taken");
  return members[0];
}

ConceptPtr fromResult(const Keywords& k) {
  const auto r = k.concept<ResultConcept>("RESULTAT");
  const mesh::Mesh& mesh = r->model->mesh();
  const std::string name = k.text("NOM_CHAM"), cmp = k.text("NOM_CMP");
  const bool hasNode = k.has("NOEUD") || k.has("GROUP_NO"), hasCell = k.has("MAILLE") || k.has("GROUP_MA");
  const int node = hasNode ? oneOf(k, mesh, true) : -1;
  const int cell = hasCell ? oneOf(k, mesh, false) : -1;
  std::vector<double> x, y;
  std::string where;
  for (const ResultInstant* i : selectedInstants(*r, k)) {
    double v = 0;
    if (const CellField* f = ResultConcept::cellField(*i, name)) {
      const bool gauss = f->location == CellLocation::GaussPoints;
      if (cell < 0)
        throw Error(name + " is a field " + (gauss ? "at Gauss points: give the cell (MAILLE or GROUP_MA) and POINT"
                                                   : "at cell nodes: give the cell (MAILLE or GROUP_MA) and the node"));
      const auto at = std::find(f->cells.begin(), f->cells.end(), cell);
      if (at == f->cells.end()) throw Error("the field " + name + " has no value on cell " + mesh.cellName(cell));
      const std::size_t kc = static_cast<std::size_t>(at - f->cells.begin());
      int point = 0;
      if (gauss) {
        if (hasNode) throw Error(name + " is a field at Gauss points: give POINT, not a node");
        point = k.has("POINT") ? static_cast<int>(k.integer("POINT")) - 1 : 0;
        if (point >= pointsOf(*f, kc))
          throw Error("POINT=" + std::to_string(point + 1) + ": cell " + mesh.cellName(cell) + " has " +
                      std::to_string(pointsOf(*f, kc)) + " Gauss points in " + name);
        where = "cell " + mesh.cellName(cell) + " point " + std::to_string(point + 1);
      } else {
        if (!hasNode) throw Error(name + " is a field at cell nodes: give the node (NOEUD or GROUP_NO)");
        const auto nodes = mesh.cellNodes(cell);
        const auto local = std::find(nodes.begin(), nodes.end(), node);
        if (local == nodes.end())
          throw Error("node " + mesh.nodeName(node) + " is not a node of cell " + mesh.cellName(cell));
        point = static_cast<int>(local - nodes.begin());
        where = "cell " + mesh.cellName(cell) + " node " + mesh.nodeName(node);
      }
      const int c = componentIndex(f->components, cmp, name);
      v = f->values[static_cast<std::size_t>(f->offsets[kc]) + static_cast<std::size_t>(point) * f->components.size() +
                    static_cast<std::size_t>(c)];
    } else {
      const mesh::NodalField& nodal = ResultConcept::nodalField(*i, name);
      if (!hasNode) throw Error(name + " is a nodal field: give the node (NOEUD or GROUP_NO)");
      if (k.has("POINT")) throw Error(name + " is a nodal field: POINT designates a Gauss point");
      const int c = componentIndex(nodal, cmp, name);
      v = nodal.values[static_cast<std::size_t>(node) * nodal.components.size() + static_cast<std::size_t>(c)];
      where = "node " + mesh.nodeName(node);
    }
    x.push_back(i->time);
    y.push_back(v);
  }
  for (std::size_t i = 1; i < x.size(); ++i)
    if (!(x[i] > x[i - 1]))
      throw Error("the instants chosen do not increase (INST " + format::shortest(x[i - 1]) + " then " +
                  format::shortest(x[i]) + "): a function needs increasing abscissas");
  auto f = std::make_shared<expr::Tabulated>(k.has("NOM_PARA") ? k.text("NOM_PARA") : "INST", x, y,
                                             tabulatedOptionsOf(k));
  if (k.integer("INFO") >= 2) {
    std::string s = "RECU_FONCTION " + name + " " + cmp + " at " + where + ":\n";
    for (std::size_t i = 0; i < x.size(); ++i) s += "  " + format::shortest(x[i]) + "  " + format::shortest(y[i]) + "\n";
    Messages::info(s);
  }
  return std::make_shared<FunctionConcept>("fonction_sdaster", f);
}

ConceptPtr recuFonction(const Keywords& k, Session&, ConceptPtr) {
  if (k.has("RESULTAT")) return fromResult(k);
  const auto& table = k.concept<TableConcept>("TABLE")->table;
  const std::string px = k.text("PARA_X"), py = k.text("PARA_Y");
  const auto& cx = table.column(px);
  const auto& cy = table.column(py);
  if (cx.type == post::ColumnType::Text || cy.type == post::ColumnType::Text)
    throw Error("PARA_X and PARA_Y must be numeric columns (" + (cx.type == post::ColumnType::Text ? px : py) + " holds texts)");
  std::vector<double> x, y;
  for (int r : table.select(tableFiltersOf(k))) {
    const auto& vx = cx.values[r];
    const auto& vy = cy.values[r];
    if (vx.empty() || vy.empty()) continue;
    x.push_back(vx.number());
    y.push_back(vy.number());
  }
  if (x.empty()) throw Error("no row of the table (after FILTRE) gives both " + px + " and " + py);
  if (k.text("VERIF") == "NON") {
    std::vector<std::size_t> order(x.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
    std::vector<double> xs, ys;
    for (auto i : order) { xs.push_back(x[i]); ys.push_back(y[i]); }
    x = xs; y = ys;
  }
  auto f = std::make_shared<expr::Tabulated>(k.has("NOM_PARA") ? k.text("NOM_PARA") : px, x, y, tabulatedOptionsOf(k));
  if (k.integer("INFO") >= 2) {
    std::string s = "RECU_FONCTION " + px + " -> " + py + ":\n";
    for (std::size_t i = 0; i < x.size(); ++i) s += "  " + format::shortest(x[i]) + "  " + format::shortest(y[i]) + "\n";
    Messages::info(s);
  }
  return std::make_shared<FunctionConcept>("fonction_sdaster", f);
}

RegisterOperator reg("RECU_FONCTION", recuFonction);

}  // namespace
}  // namespace aster::lang
