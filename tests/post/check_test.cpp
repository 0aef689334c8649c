// OK/NOOK decisions and the .resu layout, against code_aster's rules (its
// TEST_RESU documentation and checking sources), with numbers worked by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "post/check.hpp"

using namespace aster::post;
using Diag = CheckLine::Diag;

namespace {

CheckSpec calc(double v) {
  CheckSpec s;
  s.valeCalc = {v};
  return s;
}

}  // namespace

TEST(Check, NonRegressionUsesTheMachineTolerance) {
  const CheckSpec s = calc(4.0e-5);
  auto lines = check(4.0e-5 * (1 + 0.9e-6), s);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].diag, Diag::Ok);
  EXPECT_EQ(lines[0].reference, "NON_REGRESSION");
  EXPECT_NEAR(lines[0].error, 0.9e-4, 1e-12);  // percent
  EXPECT_NEAR(lines[0].tolerance, 1e-4, 1e-18);
  EXPECT_EQ(check(4.0e-5 * (1 + 1.1e-6), s)[0].diag, Diag::Nook);
}

TEST(Check, AReferenceAddsASecondComparison) {
  CheckSpec s = calc(3.004929245872);
  s.reference = "ANALYTIQUE";
  s.valeRefe = {3.0};
  s.precision = 1e-2;
  const auto lines = check(3.004929245872, s);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_TRUE(lines[0].ok());
  EXPECT_TRUE(lines[1].ok());
  EXPECT_EQ(lines[1].reference, "ANALYTIQUE");
  EXPECT_NEAR(lines[1].error, 100 * 0.004929245872 / 3.0, 1e-12);
  EXPECT_FALSE(check(3.031, s)[1].ok());  // 1.03% > 1%
}

TEST(Check, AbsoluteCriterionAppliesToBothComparisons) {
  // CRITERE='ABSOLU': VALE_CALC 100 within 1e-6 (absolute, not 1e-4 relative).
  CheckSpec s = calc(100.0);
  s.relative = false;
  s.reference = "SOURCE_EXTERNE";
  s.valeRefe = {101.0};
  s.precision = 2.0;
  auto lines = check(100.0 + 5e-7, s);
  EXPECT_EQ(lines[0].diag, Diag::Ok);
  EXPECT_NEAR(lines[0].error, 5e-7, 1e-12);
  EXPECT_EQ(lines[1].diag, Diag::Ok);  // |100 - 101| <= 2
  lines = check(100.0 + 2e-6, s);      // 2e-8 relative, but 2e-6 > 1e-6 absolute
  EXPECT_EQ(lines[0].diag, Diag::Nook);
  EXPECT_EQ(check(103.5, s)[1].diag, Diag::Nook);
}

TEST(Check, RelativeWithAZeroReferenceNeedsExactlyZero) {
  CheckSpec s;
  s.reference = "ANALYTIQUE";
  s.valeRefe = {0.0};
  s.precision = 0.5;  // no relative tolerance can admit anything around 0
  auto l = check(0.0, s);
  ASSERT_EQ(l.size(), 1u);
  EXPECT_EQ(l[0].diag, Diag::Ok);
  EXPECT_EQ(l[0].error, 0.0);
  l = check(1e-300, s);
  EXPECT_EQ(l[0].diag, Diag::Nook);
  EXPECT_EQ(l[0].error, 999.999999);
}

TEST(Check, ZeroValeCalcWithoutOrdreGrandeurIsSkipped) {
  const CheckSpec s = calc(0.0);
  EXPECT_EQ(check(0.0, s)[0].diag, Diag::Skip);
  EXPECT_EQ(check(5.0, s)[0].diag, Diag::Skip);  // neither OK nor NOOK
  EXPECT_TRUE(check(5.0, s)[0].ok());
  // "zero" is within the machine epsilon (2.22e-16), not below 1e-16 only.
  EXPECT_EQ(check(1.0, calc(2e-16))[0].diag, Diag::Skip);
  EXPECT_EQ(check(1.0, calc(3e-16))[0].diag, Diag::Nook);
}

TEST(Check, OrdreGrandeurScalesTheAbsoluteTolerance) {
  CheckSpec s = calc(0.0);
  s.hasOrdreGrandeur = true;
  s.ordreGrandeur = 1e-3;
  s.relative = false;
  auto l = check(9e-10, s);  // 9e-10 <= 1e-6 * 1e-3
  EXPECT_EQ(l[0].diag, Diag::Ok);
  EXPECT_DOUBLE_EQ(l[0].tolerance, 1e-9);
  EXPECT_EQ(l[0].compare, 1e-3);
  EXPECT_EQ(check(2e-9, s)[0].diag, Diag::Nook);
  // RELATIF (the default) keeps the exact-zero rule: ORDRE_GRANDEUR does not help.
  s.relative = true;
  EXPECT_EQ(check(1e-20, s)[0].diag, Diag::Nook);
  EXPECT_EQ(check(0.0, s)[0].diag, Diag::Ok);
}

TEST(Check, OrdreGrandeurNeverAppliesToTheReference) {
  CheckSpec s = calc(0.0);
  s.hasOrdreGrandeur = true;
  s.ordreGrandeur = 1e4;
  s.relative = false;
  s.reference = "ANALYTIQUE";
  s.valeRefe = {0.0};
  s.precision = 1e-3;
  const auto l = check(2e-3, s);
  EXPECT_EQ(l[0].diag, Diag::Ok);    // within 1e-6 * 1e4
  EXPECT_EQ(l[1].diag, Diag::Nook);  // not within 1e-3 * 1
  EXPECT_EQ(l[1].compare, 1.0);
}

TEST(Check, ValeAbsTakesTheAbsoluteValueOfBoth) {
  CheckSpec s = calc(-2.5);
  s.valeAbs = true;
  s.reference = "ANALYTIQUE";
  s.valeRefe = {2.5};
  const auto l = check(-2.5, s);
  EXPECT_EQ(l[0].diag, Diag::Ok);
  EXPECT_EQ(l[0].expected, 2.5);
  EXPECT_EQ(l[0].computed, 2.5);
  EXPECT_EQ(l[1].diag, Diag::Ok);
  EXPECT_EQ(check(2.5, s)[0].diag, Diag::Ok);
  s.valeAbs = false;
  EXPECT_EQ(check(2.5, s)[0].diag, Diag::Nook);
}

TEST(Check, SeveralValuesUseTheClosest) {
  CheckSpec s;
  s.valeCalc = {1.0, 2.0, 3.0};
  auto l = check(2.0000001, s);
  EXPECT_EQ(l[0].expected, 2.0);
  EXPECT_EQ(l[0].diag, Diag::Ok);
  l = check(2.9, s);
  EXPECT_EQ(l[0].expected, 3.0);
  EXPECT_EQ(l[0].diag, Diag::Nook);
}

TEST(Check, IntegersCompareWithTheSameRules) {
  CheckSpec s;
  s.valeCalc = {7};
  s.integer = true;
  EXPECT_EQ(check(7, s)[0].diag, Diag::Ok);
  EXPECT_EQ(check(8, s)[0].diag, Diag::Nook);  // 1/7 > 1e-6
  s.toleMachine = 0.2;
  EXPECT_EQ(check(8, s)[0].diag, Diag::Ok);    // 1 <= 0.2 * 7
}

TEST(Check, NotANumberIsNeverOk) {
  EXPECT_EQ(check(std::nan(""), calc(1.0))[0].diag, Diag::Nook);
}

TEST(Check, PythonReprOfFloats) {
  EXPECT_EQ(pythonRepr(0.125), "0.125");
  EXPECT_EQ(pythonRepr(300.0), "300.0");
  EXPECT_EQ(pythonRepr(0.0), "0.0");
  EXPECT_EQ(pythonRepr(-0.0), "-0.0");
  EXPECT_EQ(pythonRepr(301.105319971), "301.105319971");
  EXPECT_EQ(pythonRepr(0.0001), "0.0001");
  EXPECT_EQ(pythonRepr(1e-5), "1E-05");
  EXPECT_EQ(pythonRepr(-5.31098862756e-05), "-5.31098862756E-05");
  EXPECT_EQ(pythonRepr(1e-6 * 100), "9.999999999999999E-05");
  EXPECT_EQ(pythonRepr(1e15), "1000000000000000.0");
  EXPECT_EQ(pythonRepr(1e16), "1E+16");
  EXPECT_EQ(pythonRepr(1.5e300), "1.5E+300");
  EXPECT_EQ(pythonRepr(123456.75), "123456.75");
}

// The lines code_aster's TestResult writes: "%-4s " then columns of 16 characters,
// the two values in max(16, their lengths) + 2, all joined by one blank.
TEST(CheckFormat, NonRegressionAndReferenceLines) {
  CheckSpec s = calc(0.125);
  s.reference = "ANALYTIQUE";
  s.valeRefe = {0.1};
  s.precision = 0.5;
  const std::string text = formatLines(check(0.125, s), "XXXX");
  const std::string expected =
      "      REFERENCE        LEGENDE          VALE_REFE          VALE_CALC          ERREUR           TOLE            \n"
      " OK   NON_REGRESSION   XXXX             0.125              0.125              0.0%             9.999999999999999E-05%\n"
      " OK   ANALYTIQUE       XXXX             0.1                0.125               2.500000E+01%   50.0%           \n";
  EXPECT_EQ(text, expected);
}

TEST(CheckFormat, NookStartsInTheFirstColumnAndLongErrorsUseE) {
  const std::string text = formatLines(check(0.3, calc(0.1)), "DX");
  // error: |0.1 - 0.3| / 0.1 * 100 = 199.99999999999997 (18 characters): "%13.6e", 13 wide.
  // (0.125 above: 0.025 / 0.1 * 100 = 24.999999999999993, likewise.)
  const std::string expected =
      "      REFERENCE        LEGENDE          VALE_REFE          VALE_CALC          ERREUR           TOLE            \n"
      "NOOK  NON_REGRESSION   DX               0.1                0.3                 2.000000E+02%   9.999999999999999E-05%\n";
  EXPECT_EQ(text, expected);
}

TEST(CheckFormat, AbsoluteOrdreGrandeurAndSkip) {
  CheckSpec s = calc(0.0);
  s.hasOrdreGrandeur = true;
  s.ordreGrandeur = 1000.0;
  s.relative = false;
  // tolerance |1e-6 * 1000| = 0.001; no '%' when absolute.
  EXPECT_EQ(formatLines(check(1e-5, s), "XXXX"),
            "      ORDRE DE GRANDEUR : 1000.0          \n"
            "      REFERENCE        LEGENDE          VALE_REFE          VALE_CALC          ERREUR           TOLE            \n"
            " OK   NON_REGRESSION   XXXX             0.0                1E-05              1E-05            0.001           \n");
  EXPECT_EQ(formatLines(check(1e-5, calc(0.0)), "XXXX"),
            "      REFERENCE        LEGENDE          VALE_REFE          VALE_CALC          ERREUR           TOLE            \n"
            "SKIP  NON_REGRESSION   -                -                  -                  -                -               \n");
}

TEST(CheckFormat, WideValuesWidenBothValueColumns) {
  CheckSpec s = calc(-123456789.12345678);
  s.integer = false;
  const std::string text = formatLines(check(-123456789.12345678, s), "XXXX");
  // "-123456789.12345678" has 19 characters: both value columns are 21 wide.
  EXPECT_NE(text.find("      REFERENCE        LEGENDE          VALE_REFE             VALE_CALC             ERREUR"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find(" OK   NON_REGRESSION   XXXX             -123456789.12345678   -123456789.12345678   0.0%"),
            std::string::npos)
      << text;
}

TEST(CheckFormat, IntegersPrintAsIntegers) {
  CheckSpec s;
  s.valeCalc = {3};
  s.integer = true;
  EXPECT_NE(formatLines(check(3, s), "XXXX").find(" OK   NON_REGRESSION   XXXX             3                  3 "),
            std::string::npos);
}

// The header: "---- " and the factor keyword in 21 characters, then columns of 17
// (a blank and 16), each line trimmed, Fortran's leading blank.
TEST(CheckFormat, Header) {
  EXPECT_EQ(formatHeader({{"CHAM_NO", "DEP"}, {"NOM_CMP", "DX"}, {"NOEUD", "N3"}}),
            " ---- CHAM_NO          NOM_CMP          NOEUD\n"
            "      DEP              DX               N3\n");
  EXPECT_EQ(formatHeader({{"CHAM_ELEM", "SIG"}, {"NOM_CMP", "SIXX"}}, false),
            "---- CHAM_ELEM        NOM_CMP\n"
            "      SIG              SIXX\n");
}

TEST(CheckFormat, TextLines) {
  EXPECT_EQ(formatTextLine(true, "NON_REGRESSION", "XXXX", "TOTAL", "TOTAL", true),
            "      REFERENCE        LEGENDE          VALE_REFE                VALE_CALC               \n"
            " OK   NON_REGRESSION   XXXX             TOTAL                    TOTAL                   \n");
  EXPECT_EQ(formatTextLine(false, "ANALYTIQUE", "XXXX", "A", "B", false),
            "NOOK  ANALYTIQUE       XXXX             A                        B                       \n");
}

// TEST_FONCTION's own rules: the signed error, no ORDRE_GRANDEUR, VALE_ABS on the
// computed value only; values rounded to the tolerance (12 digits at least for
// NON_REGRESSION).
TEST(CheckFunction, RulesAndLayout) {
  CheckSpec s = calc(0.5);
  s.reference = "ANALYTIQUE";
  s.valeRefe = {0.49};
  s.precision = 0.05;
  const auto lines = checkFunctionValue(0.5, s);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].diag, Diag::Ok);
  EXPECT_EQ(lines[1].diag, Diag::Ok);
  EXPECT_NEAR(lines[1].error, (0.5 - 0.49) / 0.49 * 100, 1e-12);
  // NON_REGRESSION: 1e-6 -> 1e-4 % -> 4 + 2 digits, raised to 12: 0.5 as "%15.14f".
  // Reference: 5 % -> -int(log10 5) + 2 = 2 digits: "%5.4f".
  EXPECT_EQ(formatFunctionLines(lines, "XXXX"),
            "      REFERENCE        LEGENDE          VALE_REFE        VALE_CALC        ERREUR           TOLE             \n"
            " OK   NON_REGRESSION   XXXX             0.50000000000000 0.50000000000000 0.0E+00%         1.0E-04%         \n"
            " OK   ANALYTIQUE       XXXX             0.4900           0.5000           2.0%             5.0%             \n");
  CheckSpec z = calc(0.0);
  z.hasOrdreGrandeur = true;  // ignored by TEST_FONCTION
  z.ordreGrandeur = 1.0;
  EXPECT_EQ(checkFunctionValue(1e-12, z)[0].diag, Diag::Nook);
  EXPECT_EQ(checkFunctionValue(1e-12, z)[0].error, 999.999999);
  CheckSpec a = calc(-2.0);
  a.valeAbs = true;  // |computed| against the signed VALE_CALC
  EXPECT_EQ(checkFunctionValue(-2.0, a)[0].diag, Diag::Nook);
  a.valeCalc = {2.0};
  EXPECT_EQ(checkFunctionValue(-2.0, a)[0].diag, Diag::Ok);
}

TEST(CheckFunction, ZeroToleranceAndNotANumberStillPrint) {
  CheckSpec s = calc(0.5);
  s.toleMachine = 0.0;
  auto lines = checkFunctionValue(0.5, s);
  EXPECT_EQ(lines[0].diag, Diag::Ok);  // |0| <= 0
  EXPECT_NE(formatFunctionLines(lines, "XXXX").find(" OK   NON_REGRESSION   XXXX             0.50000000000000000"),
            std::string::npos);
  lines = checkFunctionValue(std::nan(""), calc(0.5));
  EXPECT_EQ(lines[0].diag, Diag::Nook);
  EXPECT_NE(formatFunctionLines(lines, "XXXX").find("NOOK  NON_REGRESSION"), std::string::npos);
}
