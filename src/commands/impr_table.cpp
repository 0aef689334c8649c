// IMPR_TABLE: a table (filtered, sorted, some columns) as aligned columns
// (TABLEAU, also printed on the screen) or CSV, appended to the file bound to
// UNITE, or written to <output>/<table name>.tab|.csv when the unit is not bound.
#include <cstdio>
#include <fstream>

#include "commands/table_concept.hpp"
#include "core/error.hpp"
#include "lang/operators.hpp"

namespace aster::lang {
namespace {

ConceptPtr imprTable(const Keywords& k, Session& session, ConceptPtr) {
  const auto tc = k.concept<TableConcept>("TABLE");
  const post::Table& table = tc->table;
  std::vector<int> rows = table.select(tableFiltersOf(k));
  if (!k.factor("TRI").empty()) {
    const auto& tri = k.factor("TRI")[0];
    const auto order = table.sortedRows(tri.texts("NOM_PARA"), tri.text("ORDRE", "CROISSANT") == "DECROISSANT");
    std::vector<char> keep(table.rowCount(), 0);
    for (int r : rows) keep[r] = 1;
    rows.clear();
    for (int r : order)
      if (keep[r]) rows.push_back(r);
  }
  post::Table out = table.subset(rows, k.has("NOM_PARA") ? k.texts("NOM_PARA") : std::vector<std::string>{});
  if (k.has("TITRE")) out.titles = k.texts("TITRE");
  const bool csv = k.text("FORMAT", "TABLEAU") == "CSV";
  const std::string formatR = k.text("FORMAT_R", "E12.5");
  const std::string text = csv ? out.formatCsv(formatR, k.text("SEPARATEUR", ","))
                               : out.formatTableau(formatR, k.text("SEPARATEUR", " "));
  const int unit = static_cast<int>(k.integer("UNITE"));
  std::filesystem::path path;
  auto bound = session.units.find(unit);
  std::ios::openmode mode = std::ios::out;
  if (bound != session.units.end()) {
    path = bound->second;
    mode |= std::ios::app;
  } else {
    std::string name = session.nameOf(*tc);
    path = session.outputFile(name + (csv ? ".csv" : ".tab"));
  }
  std::ofstream file(path, mode);
  file << text;
  if (!file) throw Error("cannot write the table to " + path.string());
  if (!csv) {
    std::fputs(text.c_str(), stdout);
    std::fflush(stdout);
  }
  return nullptr;
}

RegisterOperator reg("IMPR_TABLE", imprTable);

}  // namespace
}  // namespace aster::lang
