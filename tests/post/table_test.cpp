#include <gtest/gtest.h>

#include "core/error.hpp"
#include "post/table.hpp"

using namespace aster;
using post::TableValue;

namespace {
post::Table sample() {
  post::Table t;
  t.addRow({{"NOEUD", TableValue::ofText("N1")}, {"DX", TableValue::ofReal(0.5)}, {"K", TableValue::ofInteger(3)}});
  t.addRow({{"NOEUD", TableValue::ofText("N2")}, {"DX", TableValue::ofReal(-1.5)}});
  t.addRow({{"NOEUD", TableValue::ofText("N3")}, {"DX", TableValue::ofReal(2.0)}, {"K", TableValue::ofInteger(1)}});
  return t;
}
}  // namespace

TEST(Table, RowsColumnsAndEmptyCells) {
  const auto t = sample();
  EXPECT_EQ(t.rowCount(), 3);
  EXPECT_EQ(t.columnNames(), (std::vector<std::string>{"NOEUD", "DX", "K"}));
  EXPECT_EQ(t.column("K").type, post::ColumnType::Integer);
  EXPECT_TRUE(t.at("K", 1).empty());
  EXPECT_DOUBLE_EQ(t.at("DX", 2).real, 2.0);
  EXPECT_THROW(t.column("DY"), Error);
  post::Table bad = sample();
  EXPECT_THROW(bad.addRow({{"K", TableValue::ofText("x")}}), Error);
}

TEST(Table, FiltersAndSorting) {
  const auto t = sample();
  post::TableFilter f;
  f.column = "NOEUD";
  f.texts = {"N2", "N3"};
  EXPECT_EQ(t.select({f}), (std::vector<int>{1, 2}));
  post::TableFilter g;
  g.column = "DX";
  g.comparison = "MAXI_ABS";
  EXPECT_EQ(t.select({g}), (std::vector<int>{2}));
  g.comparison = "GT";
  g.reals = {0.0};
  EXPECT_EQ(t.select({g}), (std::vector<int>{0, 2}));
  g.comparison = "EQ";
  g.reals = {-1.5001};  // within the default relative 1e-3
  EXPECT_EQ(t.select({g}), (std::vector<int>{1}));
  post::TableFilter e;
  e.column = "K";
  e.comparison = "VIDE";
  EXPECT_EQ(t.select({e}), (std::vector<int>{1}));
  EXPECT_EQ(t.sortedRows({"DX"}, false), (std::vector<int>{1, 0, 2}));
  EXPECT_EQ(t.sortedRows({"K"}, true), (std::vector<int>{0, 2, 1}));
}

TEST(Table, CsvAndTableau) {
  const auto t = sample();
  EXPECT_EQ(t.formatCsv("F5.2"), "NOEUD,DX,K\nN1,0.50,3\nN2,-1.50,\nN3,2.00,1\n");
  const auto s = t.subset({2}, {"DX", "NOEUD"}).formatTableau("E12.5");
  EXPECT_EQ(s, "#\n         DX NOEUD\n2.00000E+00 N3   \n");
  EXPECT_EQ(post::printfFormat("e12.5"), "%12.5E");
  EXPECT_THROW(post::printfFormat("Z3"), Error);
}
