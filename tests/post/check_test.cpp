// OK/NOOK decisions, computed by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "post/check.hpp"

using namespace aster::post;

TEST(Check, NonRegressionUsesTheMachineTolerance) {
  CheckSpec s;
  s.valeCalc = 4.0e-5;
  auto lines = check(4.0e-5 * (1 + 0.9e-6), s);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_TRUE(lines[0].ok);
  EXPECT_NEAR(lines[0].error, 0.9e-4, 1e-12);  // percent
  EXPECT_FALSE(check(4.0e-5 * (1 + 1.1e-6), s)[0].ok);
}

TEST(Check, AReferenceAddsASecondComparison) {
  CheckSpec s;
  s.valeCalc = 3.004929245872;
  s.reference = "ANALYTIQUE";
  s.hasValeRefe = true;
  s.valeRefe = 3.0;
  s.precision = 1e-2;
  const auto lines = check(3.004929245872, s);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_TRUE(lines[0].ok);
  EXPECT_TRUE(lines[1].ok);
  EXPECT_NEAR(lines[1].error, 100 * 0.004929245872 / 3.0, 1e-12);
  EXPECT_FALSE(check(3.031, s)[1].ok);  // 1.03% > 1%
}

TEST(Check, AbsoluteCriterion) {
  CheckSpec s;
  s.hasValeCalc = false;
  s.reference = "ANALYTIQUE";
  s.hasValeRefe = true;
  s.valeRefe = 0.0;
  s.precision = 1e-8;
  s.relative = false;
  EXPECT_TRUE(check(5e-9, s)[0].ok);
  EXPECT_FALSE(check(2e-8, s)[0].ok);
}

TEST(Check, ZeroReferenceUsesOrdreGrandeur) {
  CheckSpec s;
  s.valeCalc = 0.0;
  s.ordreGrandeur = 1e-3;
  EXPECT_TRUE(check(1e-10, s)[0].ok);   // 1e-10 <= 1e-6 * 1e-3
  EXPECT_FALSE(check(1e-8, s)[0].ok);
}

TEST(Check, NotANumberIsNeverOk) {
  CheckSpec s;
  s.valeCalc = 1.0;
  EXPECT_FALSE(check(std::nan(""), s)[0].ok);
}

TEST(Check, FormatShowsStatusAndValues) {
  CheckSpec s;
  s.valeCalc = 0.125;
  const std::string text = formatCheck({{"FONCTION", "F"}, {"VALE_PARA", "0.5"}}, check(0.125, s), "XXXX");
  EXPECT_NE(text.find(" OK   NON_REGRESSION   XXXX             0.125            0.125"), std::string::npos) << text;
}
