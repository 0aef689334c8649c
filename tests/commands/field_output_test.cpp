// The Gauss point localizations given to the writers (lang::cellValuesOf) are
// code_aster's families in its order, typed here from their formulas: TRIA6
// FPG3 (1/6, 1/6), (2/3, 1/6), (1/6, 2/3), weights 1/6, in a plane model, FPG6
// for a field with 6 points (AXIS); QUAD8 FPG9 (corners, mid-edges, centre).
#include <gtest/gtest.h>

#include <cmath>

#include "commands/field_output.hpp"
#include "core/error.hpp"

using namespace aster;

namespace {

// A TRIA6 (M1) and a QUAD8 (M2), reference-shaped.
mesh::Mesh twoCells() {
  mesh::Mesh m;
  const double xy[14][2] = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5},              // TRIA6
                            {2, 0}, {4, 0}, {4, 2}, {2, 2}, {3, 0}, {4, 1}, {3, 2}, {2, 1}};  // QUAD8
  for (int i = 0; i < 14; ++i) m.addNode({xy[i][0], xy[i][1], 0});
  m.addCell(mesh::CellType::TRIA6, {0, 1, 2, 3, 4, 5}, "M1");
  m.addCell(mesh::CellType::QUAD8, {6, 7, 8, 9, 10, 11, 12, 13}, "M2");
  return m;
}

// One component, `tria` points on M1 and 9 on M2.
lang::CellField field(int tria) {
  lang::CellField f{"SIEF_ELGA", {"SIXX"}, {0, 1}, {0, tria, tria + 9}, {}, lang::CellLocation::GaussPoints};
  f.values.assign(tria + 9, 1.0);
  return f;
}

const mesh::GaussLocalization& localization(const mesh::CellValues& v, mesh::CellType t) {
  for (const auto& l : v.localizations)
    if (l.type == t) return l;
  throw Error("no localization");
}

}  // namespace

TEST(FieldOutput, Tria6PlaneIsFpg3AndQuad8IsFpg9) {
  const auto m = twoCells();
  const auto v = lang::cellValuesOf(m, field(3));
  const auto& t = localization(v, mesh::CellType::TRIA6);
  const double fpg3[3][2] = {{1.0 / 6, 1.0 / 6}, {2.0 / 3, 1.0 / 6}, {1.0 / 6, 2.0 / 3}};
  ASSERT_EQ(t.weights.size(), 3u);
  for (int q = 0; q < 3; ++q) {
    EXPECT_NEAR(t.points[2 * q], fpg3[q][0], 1e-15);
    EXPECT_NEAR(t.points[2 * q + 1], fpg3[q][1], 1e-15);
    EXPECT_NEAR(t.weights[q], 1.0 / 6, 1e-15);
  }
  const auto& q8 = localization(v, mesh::CellType::QUAD8);
  const double a = std::sqrt(0.6);
  const double fpg9[9][3] = {{-a, -a, 25.0 / 81}, {a, -a, 25.0 / 81}, {a, a, 25.0 / 81}, {-a, a, 25.0 / 81},
                             {0, -a, 40.0 / 81},  {a, 0, 40.0 / 81},  {0, a, 40.0 / 81}, {-a, 0, 40.0 / 81},
                             {0, 0, 64.0 / 81}};
  ASSERT_EQ(q8.weights.size(), 9u);
  for (int q = 0; q < 9; ++q) {
    EXPECT_NEAR(q8.points[2 * q], fpg9[q][0], 1e-15) << q;
    EXPECT_NEAR(q8.points[2 * q + 1], fpg9[q][1], 1e-15) << q;
    EXPECT_NEAR(q8.weights[q], fpg9[q][2], 1e-15) << q;
  }
}

TEST(FieldOutput, Tria6WithSixPointsIsAxisFpg6) {
  const auto m = twoCells();
  const auto v = lang::cellValuesOf(m, field(6));
  const auto& t = localization(v, mesh::CellType::TRIA6);
  ASSERT_EQ(t.weights.size(), 6u);
  const double b = 0.091576213509771, p2 = 0.054975871827661;
  EXPECT_NEAR(t.points[0], b, 1e-15);
  EXPECT_NEAR(t.points[1], b, 1e-15);
  EXPECT_NEAR(t.weights[0], p2, 1e-15);
  double sum = 0;
  for (double w : t.weights) sum += w;
  EXPECT_NEAR(sum, 0.5, 1e-14);
}

TEST(FieldOutput, OtherPointCountsAreRefused) { EXPECT_THROW(lang::cellValuesOf(twoCells(), field(4)), Error); }
