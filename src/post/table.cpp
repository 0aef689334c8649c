#include "post/table.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <sstream>

#include "core/error.hpp"

namespace aster::post {

const char* columnTypeName(ColumnType t) {
  switch (t) {
    case ColumnType::Real: return "R";
    case ColumnType::Integer: return "I";
    case ColumnType::Text: return "K";
  }
  return "?";
}

TableColumn& Table::addColumn(const std::string& name, ColumnType type) {
  if (hasColumn(name)) throw Error("the table already has a column " + name);
  columns_.push_back({name, type, std::vector<TableValue>(static_cast<std::size_t>(rows_))});
  return columns_.back();
}

bool Table::hasColumn(const std::string& name) const {
  for (const auto& c : columns_)
    if (c.name == name) return true;
  return false;
}

std::vector<std::string> Table::columnNames() const {
  std::vector<std::string> n;
  for (const auto& c : columns_) n.push_back(c.name);
  return n;
}

const TableColumn& Table::column(const std::string& name) const {
  for (const auto& c : columns_)
    if (c.name == name) return c;
  std::string list;
  for (const auto& c : columns_) list += (list.empty() ? "" : ", ") + c.name;
  throw Error("the table has no column " + name + " (columns: " + (list.empty() ? "none" : list) + ")");
}

static ColumnType typeOf(const TableValue& v) {
  switch (v.kind) {
    case TableValue::Kind::Integer: return ColumnType::Integer;
    case TableValue::Kind::Text: return ColumnType::Text;
    default: return ColumnType::Real;
  }
}

void Table::addRow(const std::vector<std::pair<std::string, TableValue>>& row) {
  for (const auto& [name, v] : row) {
    if (!hasColumn(name)) addColumn(name, typeOf(v));
  }
  for (auto& c : columns_) c.values.emplace_back();
  ++rows_;
  for (const auto& [name, v] : row) {
    for (auto& c : columns_) {
      if (c.name != name) continue;
      TableValue value = v;
      if (!value.empty()) {
        const bool fits = (c.type == ColumnType::Text) == (value.kind == TableValue::Kind::Text) &&
                          !(c.type == ColumnType::Integer && value.kind == TableValue::Kind::Real);
        if (!fits)
          throw Error("column " + name + " holds " + columnTypeName(c.type) + " values; cannot store " +
                      (value.kind == TableValue::Kind::Text ? "a text" : "a number") + " in it");
        if (c.type == ColumnType::Real && value.kind == TableValue::Kind::Integer) {
          value = TableValue::ofReal(double(value.integer));
        }
      }
      c.values.back() = value;
    }
  }
}

const TableValue& Table::at(const std::string& name, int row) const {
  const auto& c = column(name);
  if (row < 0 || row >= rows_)
    throw Error("row " + std::to_string(row + 1) + " is outside the table (" + std::to_string(rows_) + " rows)");
  return c.values[static_cast<std::size_t>(row)];
}

static bool nearlyEqual(double a, double b, bool relative, double precision) {
  const double d = std::abs(a - b);
  return relative ? d <= precision * std::abs(b) : d <= precision;
}

std::vector<int> Table::select(const std::vector<TableFilter>& filters) const {
  std::vector<int> rows(static_cast<std::size_t>(rows_));
  std::iota(rows.begin(), rows.end(), 0);
  for (const auto& f : filters) {
    const auto& col = column(f.column);
    std::vector<int> kept;
    const std::string& op = f.comparison;
    if (op == "MAXI" || op == "MAXI_ABS" || op == "MINI" || op == "MINI_ABS") {
      if (col.type == ColumnType::Text) throw Error("FILTRE " + op + " needs a numeric column; " + f.column + " holds texts");
      const bool absolute = op.size() > 4 && op.substr(op.size() - 3) == "ABS";
      const bool maxi = op.rfind("MAXI", 0) == 0;
      int best = -1;
      double bestValue = 0;
      for (int r : rows) {
        const auto& v = col.values[r];
        if (v.empty()) continue;
        const double x = absolute ? std::abs(v.number()) : v.number();
        if (best < 0 || (maxi ? x > bestValue : x < bestValue)) { best = r; bestValue = x; }
      }
      if (best >= 0) kept.push_back(best);
      rows = kept;
      continue;
    }
    for (int r : rows) {
      const auto& v = col.values[r];
      bool keep = false;
      if (op == "VIDE") keep = v.empty();
      else if (op == "NON_VIDE") keep = !v.empty();
      else if (v.empty()) keep = false;
      else if (v.kind == TableValue::Kind::Text) {
        if (f.texts.empty()) throw Error("FILTRE on " + f.column + ": the column holds texts; give VALE_K");
        bool any = false;
        for (const auto& t : f.texts) {
          const int c = v.text.compare(t);
          any = any || (op == "EQ" ? c == 0 : op == "NE" ? c != 0 : op == "LT" ? c < 0 : op == "LE" ? c <= 0
                        : op == "GT" ? c > 0 : c >= 0);
        }
        keep = op == "NE" ? std::all_of(f.texts.begin(), f.texts.end(), [&](const std::string& t) { return v.text != t; }) : any;
      } else {
        if (f.reals.empty()) throw Error("FILTRE on " + f.column + ": the column holds numbers; give VALE or VALE_I");
        const double x = v.number();
        if (op == "NE") {
          keep = true;
          for (double y : f.reals) keep = keep && !nearlyEqual(x, y, f.relative, f.precision);
        } else {
          for (double y : f.reals) {
            keep = keep || (op == "EQ" ? nearlyEqual(x, y, f.relative, f.precision) : op == "LT" ? x < y
                            : op == "LE" ? x <= y : op == "GT" ? x > y : op == "GE" ? x >= y : false);
          }
        }
      }
      if (keep) kept.push_back(r);
    }
    rows = kept;
  }
  return rows;
}

Table Table::subset(const std::vector<int>& rows, const std::vector<std::string>& columns) const {
  Table t;
  t.titles = titles;
  std::vector<const TableColumn*> cols;
  if (columns.empty()) {
    for (const auto& c : columns_) cols.push_back(&c);
  } else {
    for (const auto& n : columns) cols.push_back(&column(n));
  }
  for (const auto* c : cols) {
    auto& nc = t.addColumn(c->name, c->type);
    for (int r : rows) nc.values.push_back(c->values.at(static_cast<std::size_t>(r)));
  }
  t.rows_ = static_cast<int>(rows.size());
  return t;
}

std::vector<int> Table::sortedRows(const std::vector<std::string>& keys, bool descending) const {
  std::vector<int> rows(static_cast<std::size_t>(rows_));
  std::iota(rows.begin(), rows.end(), 0);
  std::vector<const TableColumn*> cols;
  for (const auto& k : keys) cols.push_back(&column(k));
  auto less = [&](int a, int b) {
    for (const auto* c : cols) {
      const auto& x = c->values[a];
      const auto& y = c->values[b];
      if (x.empty() != y.empty()) return x.empty();
      if (x.empty()) continue;
      if (x.kind == TableValue::Kind::Text) {
        if (x.text != y.text) return x.text < y.text;
      } else if (x.number() != y.number()) {
        return x.number() < y.number();
      }
    }
    return false;
  };
  std::stable_sort(rows.begin(), rows.end(), [&](int a, int b) { return descending ? less(b, a) : less(a, b); });
  return rows;
}

std::string printfFormat(const std::string& fortran) {
  std::string f = fortran;
  for (auto& ch : f) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  if (f.empty() || (f[0] != 'E' && f[0] != 'F' && f[0] != 'G' && f[0] != 'D'))
    throw Error("FORMAT_R='" + fortran + "': expected a Fortran edit descriptor such as E12.5, F10.3 or G12.5");
  const auto dot = f.find('.');
  const std::string width = f.substr(1, dot == std::string::npos ? std::string::npos : dot - 1);
  const std::string digits = dot == std::string::npos ? "" : f.substr(dot + 1);
  for (char ch : width + digits)
    if (!std::isdigit(static_cast<unsigned char>(ch)))
      throw Error("FORMAT_R='" + fortran + "': expected a Fortran edit descriptor such as E12.5, F10.3 or G12.5");
  const char conv = f[0] == 'F' ? 'f' : f[0] == 'G' ? 'G' : 'E';
  return "%" + width + (digits.empty() ? "" : "." + digits) + conv;
}

std::string formatCell(const TableValue& v, const std::string& printfReal) {
  char buf[64];
  switch (v.kind) {
    case TableValue::Kind::Empty: return "-";
    case TableValue::Kind::Text: return v.text;
    case TableValue::Kind::Integer: return std::to_string(v.integer);
    case TableValue::Kind::Real:
      std::snprintf(buf, sizeof buf, printfReal.c_str(), v.real);
      return buf;
  }
  return "";
}

static std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(' ');
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(' ') - b + 1);
}

std::string Table::formatTableau(const std::string& realFormat, const std::string& separator) const {
  const std::string pf = printfFormat(realFormat);
  std::vector<std::vector<std::string>> cells(columns_.size());
  std::vector<std::size_t> width(columns_.size());
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    width[c] = columns_[c].name.size();
    for (const auto& v : columns_[c].values) {
      cells[c].push_back(trim(formatCell(v, pf)));
      width[c] = std::max(width[c], cells[c].back().size());
    }
  }
  std::ostringstream out;
  out << "#\n";
  for (const auto& t : titles) out << "#" << t << "\n";
  auto pad = [](const std::string& s, std::size_t w, bool right) {
    const std::string fill(w > s.size() ? w - s.size() : 0, ' ');
    return right ? fill + s : s + fill;
  };
  for (std::size_t c = 0; c < columns_.size(); ++c)
    out << (c ? separator : "") << pad(columns_[c].name, width[c], columns_[c].type != ColumnType::Text);
  out << "\n";
  for (int r = 0; r < rows_; ++r) {
    for (std::size_t c = 0; c < columns_.size(); ++c)
      out << (c ? separator : "") << pad(cells[c][r], width[c], columns_[c].type != ColumnType::Text);
    out << "\n";
  }
  return out.str();
}

std::string Table::formatCsv(const std::string& realFormat, const std::string& separator) const {
  const std::string pf = printfFormat(realFormat);
  std::ostringstream out;
  for (std::size_t c = 0; c < columns_.size(); ++c) out << (c ? separator : "") << columns_[c].name;
  out << "\n";
  for (int r = 0; r < rows_; ++r) {
    for (std::size_t c = 0; c < columns_.size(); ++c) {
      const auto& v = columns_[c].values[r];
      out << (c ? separator : "") << (v.empty() ? std::string() : trim(formatCell(v, pf)));
    }
    out << "\n";
  }
  return out.str();
}

}  // namespace aster::post
