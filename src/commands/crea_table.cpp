// CREA_TABLE LISTE: a table from columns of reals (LISTE_R), integers (LISTE_I)
// or texts (LISTE_K); shorter columns leave empty cells.
#include "commands/table_concept.hpp"
#include "core/error.hpp"
#include "lang/operators.hpp"

namespace aster::lang {
namespace {

ConceptPtr creaTable(const Keywords& k, Session&, ConceptPtr) {
  post::Table table;
  std::size_t rows = 0;
  for (const auto& occ : k.factor("LISTE")) {
    const auto type = occ.has("LISTE_R") ? post::ColumnType::Real
                      : occ.has("LISTE_I") ? post::ColumnType::Integer : post::ColumnType::Text;
    const std::string key = occ.has("LISTE_R") ? "LISTE_R" : occ.has("LISTE_I") ? "LISTE_I" : "LISTE_K";
    rows = std::max(rows, occ.values(key).size());
    table.addColumn(occ.text("PARA"), type);
  }
  for (std::size_t r = 0; r < rows; ++r) {
    std::vector<std::pair<std::string, post::TableValue>> row;
    for (const auto& occ : k.factor("LISTE")) {
      const std::string key = occ.has("LISTE_R") ? "LISTE_R" : occ.has("LISTE_I") ? "LISTE_I" : "LISTE_K";
      const auto& vals = occ.values(key);
      if (r >= vals.size()) continue;
      const auto& v = vals[r];
      row.push_back({occ.text("PARA"), key == "LISTE_R" ? post::TableValue::ofReal(v.real)
                                       : key == "LISTE_I" ? post::TableValue::ofInteger(v.integer)
                                                          : post::TableValue::ofText(v.text)});
    }
    table.addRow(row);
  }
  if (k.has("TITRE")) table.titles = k.texts("TITRE");
  return std::make_shared<TableConcept>(table);
}

RegisterOperator reg("CREA_TABLE", creaTable);

}  // namespace
}  // namespace aster::lang
