// IMPR_TABLE: a table (filtered, sorted, some columns) as aligned columns
// (TABLEAU, also printed on the screen) or CSV, appended to the file bound to
// UNITE, or written to <output>/<table name>.tab|.csv when the unit is not bound
// (later IMPR_TABLE of the run to that file follow the first). Never over an
// input of the study; the file is complete or unchanged (a full disk is an error).
#include <cstdio>

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
    const auto order = table.sortedRows(tri.texts("NOM_PARA"), tri.text("ORDRE") == "DECROISSANT");
    std::vector<char> keep(table.rowCount(), 0);
    for (int r : rows) keep[r] = 1;
    rows.clear();
    for (int r : order)
      if (keep[r]) rows.push_back(r);
  }
  post::Table out = table.subset(rows, k.has("NOM_PARA") ? k.texts("NOM_PARA") : std::vector<std::string>{});
  if (k.has("TITRE")) out.titles = k.texts("TITRE");
  const bool csv = k.text("FORMAT") == "CSV";
  const std::string formatR = k.text("FORMAT_R");
  const std::string text = csv ? out.formatCsv(formatR, (k.has("SEPARATEUR") ? k.text("SEPARATEUR") : ","))
                               : out.formatTableau(formatR, (k.has("SEPARATEUR") ? k.text("SEPARATEUR") : " "));
  const int unit = static_cast<int>(k.integer("UNITE"));
  std::filesystem::path path;
  auto bound = session.units.find(unit);
  bool keep;
  if (bound != session.units.end()) {
    path = bound->second;
    session.checkUnitWritable(unit, path);
    keep = true;
  } else {
    // A second IMPR_TABLE of the run to the same file follows the first.
    const std::string name = session.nameOf(*tc);
    path = session.outputFile(name + (csv ? ".csv" : ".tab"));
    if (!session.inputOf(path).empty()) path = session.files.fresh(path.parent_path(), name, csv ? ".csv" : ".tab");
    keep = session.files.written(path);
  }
  appendAtomically(path, text, keep, &session.files);
  if (!csv) {
    std::fputs(text.c_str(), stdout);
    std::fflush(stdout);
  }
  return nullptr;
}

RegisterOperator reg("IMPR_TABLE", imprTable);

}  // namespace
}  // namespace aster::lang
