// TEST_TABLE: checks one cell of a table (the single row left by FILTRE) or a
// reduction of a column (TYPE_TEST: SOMM_ABS, SOMM, MAX, MIN over the rows left).
#include <algorithm>
#include <cmath>

#include "commands/check_keywords.hpp"
#include "commands/table_concept.hpp"
#include "core/error.hpp"
#include "core/number_format.hpp"
#include "lang/operators.hpp"
#include "post/check.hpp"

namespace aster::lang {
namespace {

ConceptPtr testTable(const Keywords& k, Session& session, ConceptPtr) {
  const auto tc = k.concept<TableConcept>("TABLE");
  const auto& table = tc->table;
  const std::string para = k.text("NOM_PARA");
  const auto& col = table.column(para);
  const auto rows = table.select(tableFiltersOf(k));
  std::vector<std::pair<std::string, std::string>> what{{"TABLE", session.nameOf(*tc)}, {"NOM_PARA", para}};
  for (const auto& f : k.factor("FILTRE")) {
    std::string v;
    if (f.has("VALE")) for (double x : f.reals("VALE")) v += (v.empty() ? "" : ",") + format::asterValue(x);
    if (f.has("VALE_I")) for (double x : f.reals("VALE_I")) v += (v.empty() ? "" : ",") + format::asterValue(x);
    if (f.has("VALE_K")) for (const auto& x : f.texts("VALE_K")) v += (v.empty() ? "" : ",") + x;
    what.push_back({"FILTRE " + f.text("NOM_PARA"), f.text("CRIT_COMP") + (v.empty() ? "" : " " + v)});
  }
  if (k.has("VALE_CALC_K")) {
    if (k.has("TYPE_TEST")) throw Error("TYPE_TEST needs a numeric column, not VALE_CALC_K");
    if (rows.size() != 1)
      throw Error("after FILTRE, " + std::to_string(rows.size()) + " rows remain; the check needs exactly one");
    const auto& v = col.values[rows[0]];
    const std::string got = v.kind == post::TableValue::Kind::Text ? v.text : "-";
    const std::string expected = k.text("VALE_CALC_K");
    const bool ok = got == expected;
    std::string block = " ---- TABLE " + session.nameOf(*tc) + "  NOM_PARA " + para + "\n" + (ok ? " OK   " : " NOOK ") +
                        "NON_REGRESSION   " + k.text("LEGENDE") + "   '" + expected + "'   '" + got + "'\n\n";
    session.recordCheck(block, ok);
    return nullptr;
  }
  if (col.type == post::ColumnType::Text) throw Error("column " + para + " holds texts: give VALE_CALC_K");
  double value = 0;
  if (k.has("TYPE_TEST")) {
    const std::string t = k.text("TYPE_TEST");
    double sum = 0, sumAbs = 0, mx = -HUGE_VAL, mn = HUGE_VAL;
    int count = 0;
    for (int r : rows) {
      const auto& v = col.values[r];
      if (v.empty()) continue;
      const double x = v.number();
      sum += x; sumAbs += std::abs(x); mx = std::max(mx, x); mn = std::min(mn, x);
      ++count;
    }
    if (count == 0) throw Error("TYPE_TEST='" + t + "': no value in column " + para + " after FILTRE");
    value = t == "SOMM_ABS" ? sumAbs : t == "SOMM" ? sum : t == "MAX" ? mx : mn;
    what.push_back({"TYPE_TEST", t});
  } else {
    if (rows.size() != 1)
      throw Error("after FILTRE, " + std::to_string(rows.size()) + " rows remain; the check needs exactly one (add a FILTRE or a TYPE_TEST)");
    const auto& v = col.values[rows[0]];
    if (v.empty()) throw Error("the cell of column " + para + " is empty in the selected row");
    value = v.number();
  }
  if (k.text("VALE_ABS") == "OUI") value = std::abs(value);
  Keywords spec = k;
  if (k.has("VALE_CALC_I")) spec.setSimple("VALE_CALC", {Value::ofReal(double(k.integer("VALE_CALC_I")))});
  if (k.has("VALE_REFE_I")) spec.setSimple("VALE_REFE", {Value::ofReal(double(k.integer("VALE_REFE_I")))});
  recordCheck(session, value, checkSpecOf(spec), what);
  return nullptr;
}

RegisterOperator reg("TEST_TABLE", testTable);

}  // namespace
}  // namespace aster::lang
