// DEFI_FONCTION interpolation and extension in every mode, CALC_FONC_INTERP and
// DEFI_LIST_REEL; expected values computed by hand from the points.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "core/error.hpp"
#include "expr/expression.hpp"
#include "expr/real_list.hpp"
#include "expr/tabulated.hpp"

using namespace aster::expr;

namespace {

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const aster::Error& e) {
    return e.what();
  }
  return "no error";
}

TabulatedOptions options(const char* x, const char* y, const char* left, const char* right) {
  return {interpolationFromName(x), interpolationFromName(y), extensionFromName(left),
          extensionFromName(right)};
}

}  // namespace

TEST(Tabulated, LinearInterpolation) {
  Tabulated f("INST", {0, 1, 3}, {0, 2, 3});
  EXPECT_EQ(f.parameters(), std::vector<std::string>{"INST"});
  EXPECT_EQ(f({0.0}), 0.0);
  EXPECT_EQ(f({0.5}), 1.0);
  EXPECT_EQ(f({1.0}), 2.0);
  EXPECT_EQ(f({2.0}), 2.5);
  EXPECT_EQ(f({3.0}), 3.0);
  EXPECT_DOUBLE_EQ(f({2.5}), 2.75);
}

TEST(Tabulated, Extensions) {
  const std::vector<double> x{0, 1, 3}, y{0, 2, 3};
  Tabulated constant("X", x, y, options("LIN", "LIN", "CONSTANT", "CONSTANT"));
  EXPECT_EQ(constant({-5.0}), 0.0);
  EXPECT_EQ(constant({10.0}), 3.0);
  Tabulated linear("X", x, y, options("LIN", "LIN", "LINEAIRE", "LINEAIRE"));
  EXPECT_EQ(linear({-1.0}), -2.0);  // slope 2 of the first segment
  EXPECT_EQ(linear({5.0}), 4.0);    // slope 1/2 of the last segment
  Tabulated mixed("X", x, y, options("LIN", "LIN", "EXCLU", "LINEAIRE"));
  EXPECT_EQ(mixed({5.0}), 4.0);
  EXPECT_THROW(mixed({-0.1}), aster::Error);
  // The SSNP150 ramp.
  auto rampe = Tabulated::fromPairs("INST", {0, 0, 1, 1}, options("LIN", "LIN", "LINEAIRE", "LINEAIRE"));
  EXPECT_EQ((*rampe)({0.3}), 0.3);
  EXPECT_EQ((*rampe)({1.5}), 1.5);
  EXPECT_EQ((*rampe)({-1.0}), -1.0);
}

TEST(Tabulated, ExcludedMessages) {
  auto f = Tabulated::fromPairs("INST", {0, 0, 1, 1});  // defaults: EXCLU both sides
  EXPECT_EQ(errorOf([&] { f->valueAt(2.5); }),
            "parameter INST = 2.5 is outside [0, 1] and PROL_DROITE='EXCLU'");
  EXPECT_EQ(errorOf([&] { f->valueAt(-0.25); }),
            "parameter INST = -0.25 is outside [0, 1] and PROL_GAUCHE='EXCLU'");
  EXPECT_EQ(f->valueAt(1.0), 1.0);  // the end points are inside
  EXPECT_EQ(f->valueAt(0.0), 0.0);
  EXPECT_THROW(f->valueAt(std::nan("")), aster::Error);
}

TEST(Tabulated, LogarithmicAxes) {
  // LOG-LOG is exact on power laws: y = x^2 through (1, 1) and (10, 100).
  Tabulated loglog("X", {1, 10}, {1, 100}, options("LOG", "LOG", "LINEAIRE", "LINEAIRE"));
  EXPECT_NEAR(loglog({2.0}), 4.0, 1e-13);
  EXPECT_NEAR(loglog({5.0}), 25.0, 1e-12);
  EXPECT_NEAR(loglog({100.0}), 1e4, 1e-9);  // extended with the same law
  EXPECT_NEAR(loglog({0.1}), 0.01, 1e-15);
  // LIN abscissa, LOG ordinate is exact on exponentials: y = exp(x) through (0, 1), (2, e^2).
  Tabulated linlog("X", {0, 2}, {1, std::exp(2.0)}, options("LIN", "LOG", "EXCLU", "EXCLU"));
  EXPECT_NEAR(linlog({1.0}), std::exp(1.0), 1e-14);
  EXPECT_NEAR(linlog({0.5}), std::exp(0.5), 1e-14);
  // LOG abscissa, LIN ordinate is exact on logarithms: y = ln x through (1, 0), (e^2, 2).
  Tabulated loglin("X", {1, std::exp(2.0)}, {0, 2}, options("LOG", "LIN", "EXCLU", "EXCLU"));
  EXPECT_NEAR(loglin({std::exp(1.0)}), 1.0, 1e-14);
  EXPECT_NEAR(loglin({3.0}), std::log(3.0), 1e-14);
  // A LOG abscissa extended below zero has no value.
  Tabulated logext("X", {1, 10}, {1, 2}, options("LOG", "LIN", "LINEAIRE", "LINEAIRE"));
  EXPECT_NEAR(logext({0.1}), 0.0, 1e-15);
  EXPECT_THROW(logext({-1.0}), aster::Error);
}

TEST(Tabulated, Slopes) {
  // Linear pieces: slope of the segment holding x, the right one at an inner point,
  // the last one at the last point; 0 on a CONSTANT extension, the end segment's on LINEAIRE.
  Tabulated f("XF", {-0.1, 0.0, 1.0, 1.1}, {0.0, 5.0, 5.0, 0.0}, options("LIN", "LIN", "EXCLU", "CONSTANT"));
  EXPECT_DOUBLE_EQ(f.slopeAt(-0.05), 50.0);
  EXPECT_DOUBLE_EQ(f.slopeAt(0.0), 0.0);
  EXPECT_NEAR(f.slopeAt(1.05), -50.0, 1e-12);  // 1.1 - 1.0 is not exactly 0.1
  EXPECT_NEAR(f.slopeAt(1.1), -50.0, 1e-12);
  EXPECT_DOUBLE_EQ(f.slopeAt(2.0), 0.0);
  EXPECT_THROW(f.slopeAt(-0.2), aster::Error);  // PROL_GAUCHE='EXCLU'
  Tabulated g("X", {0, 1}, {1, 3}, options("LIN", "LIN", "LINEAIRE", "LINEAIRE"));
  EXPECT_DOUBLE_EQ(g.slopeAt(-4.0), 2.0);
  // The LOG laws: y = x^2 (LOG-LOG) has slope 2x; y = exp(x) (LIN-LOG) slope exp(x); y = ln x slope 1/x.
  Tabulated loglog("X", {1, 10}, {1, 100}, options("LOG", "LOG", "EXCLU", "EXCLU"));
  EXPECT_NEAR(loglog.slopeAt(3.0), 6.0, 1e-12);
  Tabulated linlog("X", {0, 2}, {1, std::exp(2.0)}, options("LIN", "LOG", "EXCLU", "EXCLU"));
  EXPECT_NEAR(linlog.slopeAt(0.5), std::exp(0.5), 1e-13);
  Tabulated loglin("X", {1, std::exp(2.0)}, {0, 2}, options("LOG", "LIN", "EXCLU", "EXCLU"));
  EXPECT_NEAR(loglin.slopeAt(4.0), 0.25, 1e-14);
}

TEST(Tabulated, SinglePoint) {
  Tabulated c("X", {2}, {7}, options("LIN", "LIN", "CONSTANT", "CONSTANT"));
  EXPECT_EQ(c({-100.0}), 7.0);
  EXPECT_EQ(c({2.0}), 7.0);
  EXPECT_EQ(c({100.0}), 7.0);
  Tabulated e("X", {2}, {7});
  EXPECT_EQ(e({2.0}), 7.0);
  EXPECT_THROW(e({2.5}), aster::Error);
  EXPECT_NE(errorOf([] { Tabulated("X", {2}, {7}, options("LIN", "LIN", "LINEAIRE", "CONSTANT")); })
                .find("single point"),
            std::string::npos);
}

TEST(Tabulated, ConstructionErrors) {
  EXPECT_EQ(errorOf([] { Tabulated("INST", {0, 1, 1, 2}, {0, 0, 0, 0}); }),
            "function of INST: abscissas must be strictly increasing, but INST[2] = 1 follows "
            "INST[1] = 1 (0-based indices)");
  EXPECT_NE(errorOf([] { Tabulated("X", {0, 2, 1}, {0, 0, 0}); }).find("X[2] = 1 follows X[1] = 2"),
            std::string::npos);
  EXPECT_EQ(errorOf([] { Tabulated("X", {0, 1}, {0}); }), "function of X: 2 abscissas but 1 ordinates");
  EXPECT_EQ(errorOf([] { Tabulated("X", {}, {}); }), "function of X has no points");
  EXPECT_NE(errorOf([] { Tabulated("X", {0, 1}, {1, 2}, options("LOG", "LIN", "EXCLU", "EXCLU")); })
                .find("INTERPOL 'LOG' on the abscissas needs positive values, but X[0] = 0"),
            std::string::npos);
  EXPECT_NE(errorOf([] { Tabulated("X", {1, 2}, {1, -2}, options("LIN", "LOG", "EXCLU", "EXCLU")); })
                .find("ordinate 1 = -2"),
            std::string::npos);
  EXPECT_NE(errorOf([] { Tabulated::fromPairs("X", {0, 1, 2}); }).find("pairs, got 3 numbers"),
            std::string::npos);
  EXPECT_NE(errorOf([] { interpolationFromName("LINE"); }).find("'LIN' or 'LOG', got 'LINE'"),
            std::string::npos);
  EXPECT_NE(errorOf([] { extensionFromName("LINEAR"); }).find("got 'LINEAR'"), std::string::npos);
}

TEST(Tabulated, TabulateAFormula) {
  auto f = Expression::compile("X**2", {"X"});
  auto t = tabulate(*f, {0.0, 0.5, 1.0});
  EXPECT_EQ(t->parameters(), std::vector<std::string>{"X"});
  EXPECT_EQ(t->ordinates(), (std::vector<double>{0.0, 0.25, 1.0}));
  EXPECT_EQ((*t)({0.75}), 0.625);  // linear between 0.25 and 1
  EXPECT_THROW((*t)({1.5}), aster::Error);  // CALC_FONC_INTERP defaults to EXCLU
  auto g = Expression::compile("X*Y", {"X", "Y"});
  EXPECT_NE(errorOf([&] { tabulate(*g, {0.0, 1.0}); }).find("takes (X, Y)"), std::string::npos);
}

TEST(RealList, CountsAndSteps) {
  // DEFI_LIST_REEL{DEBUT=0, INTERVALLE={JUSQU_A=1, NOMBRE=10}}: 0, 0.1, ..., 1.
  auto l = realList(0.0, {{1.0, 10, 0.0}});
  ASSERT_EQ(l.size(), 11u);
  for (int i = 0; i <= 10; ++i) EXPECT_NEAR(l[i], i / 10.0, 1e-15);
  EXPECT_EQ(l.back(), 1.0);
  // Two intervals, the second by step: 0, 0.5, 1, 1.25, 1.5, 1.75, 2.
  l = realList(0.0, {{1.0, 2, 0.0}, {2.0, 0, 0.25}});
  EXPECT_EQ(l, (std::vector<double>{0, 0.5, 1, 1.25, 1.5, 1.75, 2}));
  // A step of 0.1 over [0, 1] (not exact in binary) divides within the tolerance.
  EXPECT_EQ(realList(0.0, {{1.0, 0, 0.1}}).size(), 11u);
  EXPECT_EQ(realList(3.0, {}), std::vector<double>{3.0});
}

TEST(RealList, Errors) {
  EXPECT_EQ(errorOf([] { realList(0.0, {{1.0, 0, 0.3}}); }),
            "INTERVALLE 1: PAS = 0.3 does not divide [0, 1] (3.3333333333333335 steps)");
  EXPECT_EQ(errorOf([] { realList(0.0, {{1.0, 2, 0.0}, {0.5, 1, 0.0}}); }),
            "INTERVALLE 2: JUSQU_A = 0.5 must be greater than 1");
  EXPECT_EQ(errorOf([] { realList(0.0, {{1.0, 2, 0.5}}); }), "INTERVALLE 1: give exactly one of NOMBRE and PAS");
  EXPECT_EQ(errorOf([] { realList(0.0, {{1.0, 0, 0.0}}); }), "INTERVALLE 1: give exactly one of NOMBRE and PAS");
  EXPECT_EQ(errorOf([] { realList(0.0, {{1.0, -3, 0.0}}); }), "INTERVALLE 1: NOMBRE = -3 must be >= 1");
  EXPECT_EQ(errorOf([] { realList(0.0, {{1.0, 0, -0.5}}); }), "INTERVALLE 1: PAS = -0.5 must be positive");
}
