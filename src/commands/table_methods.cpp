// What a study may ask a table: tab:get('VALE_NORM', 1) (row from 1; nil for an
// empty cell), tab:column('VALE_NORM') (a list), tab:getParameters() (column
// names), tab:getNumberOfRows().
#include "commands/table_concept.hpp"
#include "core/error.hpp"
#include "lang/operators.hpp"

namespace aster::lang {
namespace {

Datum datumOf(const post::TableValue& v) {
  switch (v.kind) {
    case post::TableValue::Kind::Real: return Datum::ofReal(v.real);
    case post::TableValue::Kind::Integer: return Datum::ofInteger(v.integer);
    case post::TableValue::Kind::Text: return Datum::ofText(v.text);
    default: return Datum{};
  }
}

const std::string& columnArgument(const std::vector<Value>& args, const char* usage) {
  if (args.empty() || args[0].kind != Value::Kind::Text) throw Error(std::string("usage: ") + usage);
  return args[0].text;
}

Datum get(Concept& self, const std::vector<Value>& args, Session&) {
  const auto& t = static_cast<TableConcept&>(self).table;
  const char* usage = "tab:get('VALE_NORM', 1) (a column name, then a row number from 1)";
  const auto& name = columnArgument(args, usage);
  if (args.size() != 2 || !args[1].isNumber()) throw Error(std::string("usage: ") + usage);
  return datumOf(t.at(name, static_cast<int>(args[1].real) - 1));
}

Datum column(Concept& self, const std::vector<Value>& args, Session&) {
  const auto& t = static_cast<TableConcept&>(self).table;
  const auto& c = t.column(columnArgument(args, "tab:column('VALE_NORM')"));
  std::vector<Datum> out;
  for (const auto& v : c.values) out.push_back(datumOf(v));
  return Datum::ofList(out);
}

Datum parameters(Concept& self, const std::vector<Value>&, Session&) {
  std::vector<Datum> out;
  for (const auto& n : static_cast<TableConcept&>(self).table.columnNames()) out.push_back(Datum::ofText(n));
  return Datum::ofList(out);
}

Datum rows(Concept& self, const std::vector<Value>&, Session&) {
  return Datum::ofInteger(static_cast<TableConcept&>(self).table.rowCount());
}

RegisterMethod m1("table_sdaster", "get", get);
RegisterMethod m2("table_sdaster", "column", column);
RegisterMethod m3("table_sdaster", "getParameters", parameters);
RegisterMethod m4("table_sdaster", "getNumberOfRows", rows);

}  // namespace
}  // namespace aster::lang
