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
  // code_aster opens each TEST_TABLE with a blank line and a rule of 80 dashes.
  const std::string rule = "\n" + std::string(80, '-') + "\n";
  CheckWhat what{{"TABLE", session.nameOf(*tc)}, {"NOM_PARA", para}};
  if (k.has("TYPE_TEST")) what.push_back({"TYPE_TEST", k.text("TYPE_TEST")});
  // A real VALE_CALC may check an integer column too (compared as a real).
  const std::string kind = k.has("VALE_CALC_K") ? "K" : k.has("VALE_CALC_I") ? "I" : "R";
  const std::string columnKind = post::columnTypeName(col.type);
  if (kind != columnKind && !(kind == "R" && columnKind == "I"))
    throw Error("column " + para + " holds " + (col.type == post::ColumnType::Text ? "texts: give VALE_CALC_K"
                                                : col.type == post::ColumnType::Integer ? "integers: give VALE_CALC_I"
                                                                                        : "reals: give VALE_CALC"));
  if (kind == "K") {
    if (k.has("TYPE_TEST")) throw Error("TYPE_TEST needs a numeric column, not VALE_CALC_K");
    if (rows.size() != 1)
      throw Error("after FILTRE, " + std::to_string(rows.size()) + " rows remain; the check needs exactly one");
    const auto& v = col.values[rows[0]];
    const std::string got = v.kind == post::TableValue::Kind::Text ? v.text : "";
    const std::string legende = k.has("LEGENDE") ? k.text("LEGENDE") : "XXXX";
    // As code_aster: the first of the expected texts, compared without trailing blanks.
    const auto trimmed = [](std::string t) { return t.erase(t.find_last_not_of(' ') + 1); };
    const auto same = [&](const std::string& expected) { return trimmed(expected) == trimmed(got); };
    const std::string calc = k.texts("VALE_CALC_K").front();
    std::string block = rule + post::formatHeader(what) +
                        post::formatTextLine(same(calc), "NON_REGRESSION", legende, calc, got, true);
    std::vector<CheckRecord> records{{same(calc) ? "OK" : "NOOK", "NON_REGRESSION", got, calc}};
    bool ok = same(calc);
    if (k.has("REFERENCE")) {
      if (!k.has("VALE_REFE_K")) throw Error("VALE_CALC_K needs VALE_REFE_K (the same kind of value)");
      const std::string refe = k.texts("VALE_REFE_K").front();
      block += post::formatTextLine(same(refe), k.text("REFERENCE"), legende, refe, got, false);
      records.push_back({same(refe) ? "OK" : "NOOK", k.text("REFERENCE"), got, refe});
      ok = ok && same(refe);
    }
    appendCheckRecords(session, records);
    session.recordCheck(block + "  \n", ok);
    return nullptr;
  }
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
  } else {
    if (rows.size() != 1)
      throw Error("after FILTRE, " + std::to_string(rows.size()) + " rows remain; the check needs exactly one (add a FILTRE or a TYPE_TEST)");
    const auto& v = col.values[rows[0]];
    if (v.empty()) throw Error("the cell of column " + para + " is empty in the selected row");
    value = v.number();
  }
  recordCheck(session, value, checkSpecOf(k), what, true, rule);
  return nullptr;
}

RegisterOperator reg("TEST_TABLE", testTable);

}  // namespace
}  // namespace aster::lang
