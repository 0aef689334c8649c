// SIEQ components against hand calculations.
// State 1: SIXX = 100, SIYY = 20, SIZZ = 30, SIXY = 30. In plane: centre 60,
// radius sqrt(40^2 + 30^2) = 50, principal 110 and 10; with SIZZ = 30:
// PRIN = (10, 30, 110), TRESCA = 100; trace 150, mean 50, deviator (50, -30, -20)
// and shear 30: s:s = 2500 + 900 + 400 + 2 * 900 = 5600, VMIS = sqrt(8400);
// TRIAX = 50 / sqrt(8400). The direction of 110: angle theta with tan(2 theta) = 30/40,
// cos(2 theta) = 0.8: cos theta = sqrt(0.9), sin theta = sqrt(0.1).
#include <gtest/gtest.h>

#include <cmath>

#include "post/stress_invariants.hpp"

using namespace aster;

TEST(EquivalentStresses, ComponentsInCodeAsterOrder) {
  const auto& c = post::equivalentStressComponents();
  ASSERT_EQ(static_cast<int>(c.size()), post::kEquivalentStressComponents);
  EXPECT_EQ(c[0], "VMIS");
  EXPECT_EQ(c[1], "TRESCA");
  EXPECT_EQ(c[4], "PRIN_3");
  EXPECT_EQ(c[5], "VMIS_SG");
  EXPECT_EQ(c[14], "VECT_3_Z");
  EXPECT_EQ(c[16], "TRIAX");
}

TEST(EquivalentStresses, HandComputedState) {
  const double s[4] = {100, 20, 30, 30};
  double e[17];
  post::equivalentStresses(s, e);
  EXPECT_NEAR(e[0], std::sqrt(8400.0), 1e-12);
  EXPECT_NEAR(e[1], 100, 1e-12);
  EXPECT_NEAR(e[2], 10, 1e-12);
  EXPECT_NEAR(e[3], 30, 1e-12);
  EXPECT_NEAR(e[4], 110, 1e-12);
  EXPECT_NEAR(e[5], std::sqrt(8400.0), 1e-12);
  // PRIN_1 = 10: direction (-sin, cos, 0), made positive on its largest component (y).
  EXPECT_NEAR(e[6], -std::sqrt(0.1), 1e-12);
  EXPECT_NEAR(e[7], std::sqrt(0.9), 1e-12);
  EXPECT_NEAR(e[8], 0, 1e-15);
  // PRIN_2 = 30: z.
  EXPECT_NEAR(e[9], 0, 1e-15);
  EXPECT_NEAR(e[11], 1, 1e-15);
  // PRIN_3 = 110: (cos, sin, 0).
  EXPECT_NEAR(e[12], std::sqrt(0.9), 1e-12);
  EXPECT_NEAR(e[13], std::sqrt(0.1), 1e-12);
  EXPECT_NEAR(e[15], 150, 1e-12);
  EXPECT_NEAR(e[16], 50 / std::sqrt(8400.0), 1e-12);
}

TEST(EquivalentStresses, UniaxialCompressionAndZeroState) {
  // SIXX = -60 alone: VMIS 60, TRESCA 60, PRIN (-60, 0, 0), VMIS_SG -60, TRIAX -1/3.
  const double s[4] = {-60, 0, 0, 0};
  double e[17];
  post::equivalentStresses(s, e);
  EXPECT_NEAR(e[0], 60, 1e-12);
  EXPECT_NEAR(e[1], 60, 1e-12);
  EXPECT_NEAR(e[2], -60, 1e-12);
  EXPECT_NEAR(e[5], -60, 1e-12);
  EXPECT_NEAR(e[16], -1.0 / 3, 1e-12);
  const double z[4] = {0, 0, 0, 0};
  post::equivalentStresses(z, e);
  for (int i : {0, 1, 2, 3, 4, 5, 15, 16}) EXPECT_EQ(e[i], 0.0) << i;
}
