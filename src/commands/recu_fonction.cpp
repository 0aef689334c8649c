// RECU_FONCTION: a tabulated function (fonction_sdaster) from two columns of a
// table, after FILTRE.
#include <algorithm>
#include <numeric>

#include "commands/function_concepts.hpp"
#include "core/number_format.hpp"
#include "commands/table_concept.hpp"
#include "core/error.hpp"
#include "core/messages.hpp"
#include "expr/tabulated.hpp"
#include "lang/operators.hpp"

namespace aster::lang {
namespace {

ConceptPtr recuFonction(const Keywords& k, Session&, ConceptPtr) {
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
