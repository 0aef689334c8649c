// The number formatters: each against the text C's printf defines for it, and
// the shortest form against reading it back.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>

#include "core/number_format.hpp"

using namespace aster;

TEST(NumberFormat, ShortestReadsBackWithTheFewestDigits) {
  EXPECT_EQ(format::shortest(0.1), "0.1");
  EXPECT_EQ(format::shortest(2.5), "2.5");
  EXPECT_EQ(format::shortest(0.0), "0");
  EXPECT_EQ(format::shortest(1e-5), "1e-05");
  for (double v : {1.0 / 3.0, -2.0 / 7.0, 6.02214076e23, 4.9e-324}) {
    const std::string text = format::shortest(v);
    EXPECT_EQ(std::strtod(text.c_str(), nullptr), v) << text;
  }
  // 1/3 needs all 16 or 17 digits; 0.1 only one.
  EXPECT_GE(format::shortest(1.0 / 3.0).size(), 18u);
}

TEST(NumberFormat, ShortestWritesIntegersPlainly) {
  EXPECT_EQ(format::shortest(1000.0), "1000");
  EXPECT_EQ(format::shortest(-123456789.0), "-123456789");
  EXPECT_EQ(format::shortest(1e20), "1e+20");
}

TEST(NumberFormat, ShortestNamesNonFiniteValues) {
  EXPECT_EQ(format::shortest(std::numeric_limits<double>::quiet_NaN()), "nan");
  EXPECT_EQ(format::shortest(-std::numeric_limits<double>::quiet_NaN()), "nan");
  EXPECT_EQ(format::shortest(HUGE_VAL), "inf");
  EXPECT_EQ(format::shortest(-HUGE_VAL), "-inf");
}

TEST(NumberFormat, SignificantDigits) {
  EXPECT_EQ(format::significant(123456.789, 3), "1.23e+05");
  EXPECT_EQ(format::significant(0.5, 10), "0.5");
  EXPECT_EQ(format::significant(1.0 / 3.0, 6), "0.333333");
}

TEST(NumberFormat, AsterValueHasTwelveDigitsAndCapitals) {
  EXPECT_EQ(format::asterValue(1.5e-5), "1.5E-05");
  EXPECT_EQ(format::asterValue(1.0 / 3.0), "0.333333333333");
  EXPECT_EQ(format::asterValue(100.0), "100");
}

TEST(NumberFormat, ScientificDecimals) {
  EXPECT_EQ(format::scientific(0.0015, 2), "1.50E-03");
  EXPECT_EQ(format::scientific(-2.0, 3), "-2.000E+00");
  EXPECT_EQ(format::scientificAligned(1.5, 8), " 1.50000000E+00");
  EXPECT_EQ(format::scientificAligned(-1.5, 8), "-1.50000000E+00");
}
