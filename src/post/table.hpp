// code_aster's table_sdaster: named columns holding reals, integers or texts,
// read by rows. A cell may be empty (a row that did not give that column).
// Filters, sorting and the text forms IMPR_TABLE writes (TABLEAU, CSV).
#pragma once
#include <string>
#include <vector>

namespace aster::post {

enum class ColumnType { Real, Integer, Text };
const char* columnTypeName(ColumnType t);  // "R", "I", "K"

struct TableValue {
  enum class Kind { Empty, Real, Integer, Text };
  Kind kind = Kind::Empty;
  double real = 0.0;
  long long integer = 0;
  std::string text;
  static TableValue ofReal(double v) { TableValue t; t.kind = Kind::Real; t.real = v; return t; }
  static TableValue ofInteger(long long v) { TableValue t; t.kind = Kind::Integer; t.integer = v; t.real = double(v); return t; }
  static TableValue ofText(std::string v) { TableValue t; t.kind = Kind::Text; t.text = std::move(v); return t; }
  bool empty() const { return kind == Kind::Empty; }
  bool isNumber() const { return kind == Kind::Real || kind == Kind::Integer; }
  double number() const { return kind == Kind::Integer ? double(integer) : real; }
};

struct TableColumn {
  std::string name;
  ColumnType type = ColumnType::Real;
  std::vector<TableValue> values;  // one per row (Empty where not given)
};

// One row selection condition, as FILTRE gives it.
struct TableFilter {
  std::string column;
  std::string comparison = "EQ";  // EQ NE LT LE GT GE VIDE NON_VIDE MAXI MAXI_ABS MINI MINI_ABS
  std::vector<double> reals;      // VALE or VALE_I (as reals)
  std::vector<std::string> texts; // VALE_K
  bool relative = true;           // CRITERE for EQ / NE on reals
  double precision = 1e-3;
};

class Table {
 public:
  // Adds an empty column (filled with empty cells up to rowCount()); throws on a
  // duplicate name.
  TableColumn& addColumn(const std::string& name, ColumnType type);
  bool hasColumn(const std::string& name) const;
  // Throws aster::Error listing the columns when absent.
  const TableColumn& column(const std::string& name) const;
  const std::vector<TableColumn>& columns() const { return columns_; }
  std::vector<std::string> columnNames() const;
  int rowCount() const { return rows_; }

  // Appends a row; columns it names that do not exist yet are created with the
  // type of the value. Columns it does not name get an empty cell. A value whose
  // kind does not fit its column throws (an integer is accepted in a real column).
  void addRow(const std::vector<std::pair<std::string, TableValue>>& row);

  const TableValue& at(const std::string& column, int row) const;

  // Rows meeting every filter, in order.
  std::vector<int> select(const std::vector<TableFilter>& filters) const;
  // A new table made of the given rows (in that order) and columns (all when empty).
  Table subset(const std::vector<int>& rows, const std::vector<std::string>& columns = {}) const;
  // Row order sorting by the keys, most significant first (stable; empty cells first).
  std::vector<int> sortedRows(const std::vector<std::string>& keys, bool descending) const;

  // Aligned columns with a header line, reals with a Fortran-like format
  // ("E12.5", "F10.3", "G12.5"); empty cells print as "-".
  std::string formatTableau(const std::string& realFormat = "E12.5", const std::string& separator = " ") const;
  std::string formatCsv(const std::string& realFormat = "E12.5", const std::string& separator = ",") const;

  std::vector<std::string> titles;

 private:
  std::vector<TableColumn> columns_;
  int rows_ = 0;
};

// printf format from a Fortran-like edit descriptor: "E12.5" -> "%12.5E".
std::string printfFormat(const std::string& fortran);
std::string formatCell(const TableValue& v, const std::string& printfReal);

}  // namespace aster::post
