// FORMULE's context: names given with the expression. Real constants are
// substituted at compile time; functions are called by name. Expected values by hand.
#include <gtest/gtest.h>

#include <functional>

#include "core/error.hpp"
#include "expr/constant.hpp"
#include "expr/dual.hpp"
#include "expr/expression.hpp"
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

ExpressionContext constants(std::vector<std::pair<std::string, double>> c) { return {std::move(c), {}}; }

}  // namespace

TEST(ExpressionContext, ConstantIsSubstitutedAtCompileTime) {
  const auto f = Expression::compile("A*X", {"X"}, constants({{"A", 2.5}}));
  EXPECT_EQ((*f)({3.0}), 7.5);
  EXPECT_EQ((*f)({-0.4}), -1.0);
  // A constant, the parameter, the product: no lookup left at run time.
  ASSERT_EQ(f->code().size(), 3u);
  EXPECT_EQ(f->code()[0].op, OpCode::Constant);
  // Constants fold with each other: A*B + X is one constant plus X.
  const auto g = Expression::compile("A*B + X", {"X"}, constants({{"A", 2.5}, {"B", 4.0}}));
  EXPECT_EQ(g->code().size(), 3u);
  EXPECT_EQ((*g)({1.0}), 11.0);
}

TEST(ExpressionContext, CallsFormulasAndFunctionsByName) {
  ExpressionContext c;
  c.constants = {{"B", 3.0}};
  c.functions = {{"G", Expression::compile("X**2 + 1", {"X"})},
                 {"T", std::make_shared<Tabulated>("INST", std::vector<double>{0.0, 2.0},
                                                   std::vector<double>{0.0, 4.0})},
                 {"C", std::make_shared<Constant>(0.5)},
                 {"P", Expression::compile("X*Y", {"X", "Y"})}};
  // B*G(X + 1) + T(X/2) + C(7) + P(X, 2) at X = 2: 3*10 + 2 + 0.5 + 4.
  const auto f = Expression::compile("B*G(X + 1) + T(X/2) + C(7) + P(X, 2)", {"X"}, c);
  EXPECT_EQ((*f)({2.0}), 36.5);
  EXPECT_EQ(f->evaluateChecked(std::vector<double>{2.0}.data()), 36.5);
  // A function used twice is one callee.
  const auto twice = Expression::compile("G(X) - G(-X)", {"X"}, c);
  EXPECT_EQ((*twice)({1.5}), 0.0);
}

TEST(ExpressionContext, DerivativesThroughACalledFormula) {
  ExpressionContext c;
  c.functions = {{"G", Expression::compile("X**3", {"X"})}};
  const auto f = Expression::compile("2*G(X*Y)", {"X", "Y"}, c);
  // f = 2 x^3 y^3: df/dx = 6 x^2 y^3, df/dy = 6 x^3 y^2; at (1, 2): 48 and 24.
  using D = Dual1<2>;
  const D args[2] = {D::variable(1.0, 0), D::variable(2.0, 1)};
  const D r = f->evaluateT(args);
  EXPECT_EQ(r.v, 16.0);
  EXPECT_EQ(r.d[0], 48.0);
  EXPECT_EQ(r.d[1], 24.0);
  // A tabulated function has no derivative to give.
  c.functions = {{"T", std::make_shared<Tabulated>("X", std::vector<double>{0.0, 1.0},
                                                   std::vector<double>{0.0, 1.0})}};
  const auto t = Expression::compile("T(X)", {"X"}, c);
  const Dual1<1> x[1] = {Dual1<1>::variable(0.5, 0)};
  EXPECT_EQ(errorOf([&] { t->evaluateT(x); }),
            "function 'T' called by \"T(X)\" is not a formula given as a text: it cannot be differentiated exactly");
}

TEST(ExpressionContext, CheckedEvaluationNamesTheCalledFunction) {
  ExpressionContext c;
  c.functions = {{"G", Expression::compile("log(X)", {"X"})}};
  const auto f = Expression::compile("1 + G(X - 1)", {"X"}, c);
  const double x = 0.5;
  EXPECT_EQ(errorOf([&] { f->evaluateChecked(&x); }),
            "log of a negative number (log(-0.5)) at column 1 of \"log(X)\", with X = -0.5");
}

TEST(ExpressionContext, Errors) {
  EXPECT_EQ(errorOf([] { Expression::compile("X", {"X"}, constants({{"X", 1.0}})); }),
            "context name 'X' is also a parameter (NOM_PARA)");
  EXPECT_EQ(errorOf([] { Expression::compile("X", {"X"}, constants({{"1A", 1.0}})); }),
            "context name '1A' is not a valid name");
  EXPECT_EQ(errorOf([] { Expression::compile("X", {"X"}, constants({{"pi", 3.0}})); }),
            "context name 'pi' is reserved (a function or a constant)");
  EXPECT_EQ(errorOf([] { Expression::compile("A*Y", {"X"}, constants({{"A", 1.0}})); }),
            "unknown name 'Y' at column 3 (parameters: X; context: A) in \"A*Y\"");
  ExpressionContext c;
  c.functions = {{"G", Expression::compile("X", {"X"})}};
  EXPECT_EQ(errorOf([&] { Expression::compile("G(X, 1)", {"X"}, c); }),
            "function 'G' takes 1 argument (X), got 2 at column 1 in \"G(X, 1)\"");
  EXPECT_EQ(errorOf([&] { Expression::compile("G*X", {"X"}, c); }),
            "function 'G' at column 1 must be called with arguments in parentheses in \"G*X\"");
}
