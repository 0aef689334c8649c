// Parser precedence, tricky inputs and evaluation of compiled FORMULE expressions.
// Expected values are Python's results for the same strings (python3 -c "print(...)").
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "expr/dual.hpp"
#include "expr/expression.hpp"

using aster::expr::Expression;

namespace {

double eval(const std::string& text, std::initializer_list<double> args = {},
            const std::vector<std::string>& params = {}) {
  return (*Expression::compile(text, params))(args);
}
double evalXY(const std::string& text, double x, double y) {
  return eval(text, {x, y}, {"X", "Y"});
}

}  // namespace

TEST(Expression, PythonPrecedence) {
  EXPECT_EQ(eval("-2**2"), -4.0);
  EXPECT_EQ(eval("2**3**2"), 512.0);
  EXPECT_EQ(eval("2**-1"), 0.5);
  EXPECT_EQ(eval("(-2)**2"), 4.0);
  EXPECT_EQ(eval("-2**-2"), -0.25);
  EXPECT_EQ(eval("2*3+4*5"), 26.0);
  EXPECT_EQ(eval("2+3*4**2"), 50.0);
  EXPECT_EQ(eval("10-4-3"), 3.0);     // left-associative
  EXPECT_EQ(eval("64/4/2"), 8.0);     // left-associative
  EXPECT_EQ(eval("2/4"), 0.5);        // true division, as Python 3
  EXPECT_EQ(eval("- -3"), 3.0);
  EXPECT_EQ(eval("+-+3"), -3.0);
  EXPECT_EQ(eval("2*-3"), -6.0);
  EXPECT_EQ(eval("-3**2*2"), -18.0);
  EXPECT_EQ(eval("2**2**-1"), std::pow(2.0, 0.5));
  EXPECT_EQ(eval("((((1))))+(2)"), 3.0);
}

TEST(Expression, NumberLiterals) {
  EXPECT_EQ(eval("1."), 1.0);
  EXPECT_EQ(eval(".5"), 0.5);
  EXPECT_EQ(eval("4.0E-05"), 4.0e-5);
  EXPECT_EQ(eval("1e3"), 1000.0);
  EXPECT_EQ(eval("1.e2"), 100.0);
  EXPECT_EQ(eval("2.5e+1"), 25.0);
  EXPECT_EQ(eval("007"), 7.0);
  EXPECT_EQ(eval("  \t3 \n"), 3.0);
}

TEST(Expression, ParametersAndFunctions) {
  EXPECT_EQ(evalXY("X - Y", 5, 2), 3.0);
  EXPECT_EQ(evalXY("Y - X", 5, 2), -3.0);
  EXPECT_DOUBLE_EQ(evalXY("sin(X)**2 + cos(X)**2", 0.7, 0), 1.0);
  EXPECT_EQ(evalXY("atan2(Y, X)", -1, 0), M_PI);
  EXPECT_EQ(evalXY("atan2(Y, X)", 0, -1), -M_PI / 2);
  EXPECT_EQ(eval("pi"), M_PI);
  EXPECT_EQ(eval("min(3, 1, 2)"), 1.0);
  EXPECT_EQ(eval("max(3, 1, 2, 7, -1)"), 7.0);
  EXPECT_EQ(evalXY("min(X, Y)", 2, -2), -2.0);
  EXPECT_EQ(evalXY("max(X, Y)", 2, -2), 2.0);
  EXPECT_EQ(evalXY("abs(X-Y)", 2, 5), 3.0);
  EXPECT_EQ(eval("sqrt(16)"), 4.0);
  EXPECT_EQ(eval("log10(1000)"), std::log10(1000.0));
  EXPECT_EQ(eval("exp(log(3))"), std::exp(std::log(3.0)));
  EXPECT_EQ(eval("tan(0.3)"), std::tan(0.3));
  EXPECT_EQ(eval("asin(0.3)+acos(0.3)"), std::asin(0.3) + std::acos(0.3));
  EXPECT_EQ(eval("atan(2)"), std::atan(2.0));
  EXPECT_EQ(eval("sinh(0.5)*cosh(0.5)-tanh(0.5)"),
            std::sinh(0.5) * std::cosh(0.5) - std::tanh(0.5));
  // pow(a, b) is a ** b, as Python's pow and math.pow (python3: pow(10, 0.1-1.1) == 0.1).
  EXPECT_EQ(eval("pow(2, 10)"), 1024.0);
  EXPECT_EQ(eval("pow(10, INST-1.1)", {2.1}, {"INST"}), std::pow(10.0, 2.1 - 1.1));
  EXPECT_DOUBLE_EQ(eval("pow(10, INST-1.1)", {0.1}, {"INST"}), 0.1);
  EXPECT_EQ(evalXY("pow(X, 0.5)", 2, 0), std::sqrt(2.0));
  EXPECT_EQ(evalXY("pow(X, Y)", -2, 3), -8.0);
  EXPECT_EQ(eval("-pow(2, 2)"), -4.0);
  EXPECT_EQ(eval("pow(2, 3)**2"), 64.0);  // a call is a primary: (2**3)**2
  // Parameter names are case-sensitive, may contain digits and underscores.
  EXPECT_EQ(eval("INST*2 + x_1", {3, 1}, {"INST", "x_1"}), 7.0);
  // A parameter may be unused; a formula may have no parameter at all.
  EXPECT_EQ(eval("2*Y", {100, 4}, {"X", "Y"}), 8.0);
}

TEST(Expression, Ssnp150Displacement) {
  auto ux = Expression::compile("-0.2*Y**3*(X-0.5)", {"X", "Y"});
  auto uy = Expression::compile("-0.05*(X-0.5)**2*(1+Y) - 0.01*Y", {"X", "Y"});
  for (double x : {0.0, 0.25, 0.9}) {
    for (double y : {0.0, 0.5, 1.0}) {
      EXPECT_DOUBLE_EQ((*ux)({x, y}), -0.2 * y * y * y * (x - 0.5));
      EXPECT_DOUBLE_EQ((*uy)({x, y}), -0.05 * (x - 0.5) * (x - 0.5) * (1 + y) - 0.01 * y);
    }
  }
}

TEST(Expression, ConstantsAreFoldedAndPowersSpecialised) {
  auto e = Expression::compile("2*3*X + 4**0.5", {"X"});
  // 2*3 folds only where it is a constant subtree: (2*3)*X + 2 -> Const Param Mul Const Add.
  EXPECT_EQ(e->code().size(), 5u);
  EXPECT_EQ((*e)({1.0}), 8.0);
  auto p = Expression::compile("X**2 + X**3 + X**-2 + X**0.5", {"X"});
  bool square = false, cube = false, integer = false, real = false;
  for (const auto& in : p->code()) {
    square |= in.op == aster::expr::OpCode::Square;
    cube |= in.op == aster::expr::OpCode::Cube;
    integer |= in.op == aster::expr::OpCode::PowerInteger;
    real |= in.op == aster::expr::OpCode::PowerConstant;
  }
  EXPECT_TRUE(square && cube && integer && real);
  EXPECT_DOUBLE_EQ((*p)({4.0}), 16.0 + 64.0 + 1.0 / 16.0 + 2.0);
  // Negative base with integer exponent is fine, as in Python.
  EXPECT_EQ(eval("X**3", {-2}, {"X"}), -8.0);
  EXPECT_EQ(eval("X**-1", {-2}, {"X"}), -0.5);
  EXPECT_EQ(eval("X**Y", {-2, 3}, {"X", "Y"}), -8.0);
}

TEST(Expression, DeepNestingUsesTheHeapFallback) {
  // 100 nested right operands need a stack deeper than the inline one.
  std::string text = "1";
  for (int i = 0; i < 100; ++i) text = "X+(" + text + ")";
  auto e = Expression::compile(text, {"X"});
  EXPECT_GT(e->stackDepth(), Expression::kInlineDepth);
  EXPECT_EQ((*e)({2.0}), 201.0);
}

TEST(Expression, EvaluatesWithDualNumbers) {
  using D = aster::expr::Dual2<2>;
  auto e = Expression::compile("X**2*Y + sin(Y)", {"X", "Y"});
  const D args[2] = {D::variable(1.5, 0), D::variable(0.5, 1)};
  const D r = e->evaluateT(args);
  EXPECT_DOUBLE_EQ(r.v, 2.25 * 0.5 + std::sin(0.5));
  EXPECT_DOUBLE_EQ(r.g[0], 2 * 1.5 * 0.5);
  EXPECT_DOUBLE_EQ(r.g[1], 2.25 + std::cos(0.5));
  EXPECT_DOUBLE_EQ(r.h[0][0], 2 * 0.5);
  EXPECT_DOUBLE_EQ(r.h[0][1], 2 * 1.5);
  EXPECT_DOUBLE_EQ(r.h[1][0], 2 * 1.5);
  EXPECT_DOUBLE_EQ(r.h[1][1], -std::sin(0.5));
}

// Long but legal formulas (generated ones can be): a sum of 300 000 terms is a
// tree as deep as it is long, compiled without recursion, evaluated natively and
// with dual numbers; 100 000 distinct constants compile in linear time.
TEST(Expression, LongSumsCompileAndEvaluate) {
  std::string text = "X";
  for (int i = 0; i < 300000; ++i) text += "+X";
  auto e = Expression::compile(text, {"X"});
  EXPECT_LE(e->stackDepth(), 2);
  EXPECT_EQ((*e)({1.5}), 1.5 * 300001);
  EXPECT_EQ(e->evaluateChecked(std::vector<double>{1.5}.data()), 1.5 * 300001);
  using D = aster::expr::Dual2<1>;
  const D x[1] = {D::variable(2.0, 0)};
  const D r = e->evaluateT(x);
  EXPECT_EQ(r.v, 2.0 * 300001);
  EXPECT_EQ(r.g[0], 300001.0);
  EXPECT_EQ(r.h[0][0], 0.0);

  std::string constants = "X";
  for (int i = 1; i <= 100000; ++i) constants += "+X*" + std::to_string(i);
  auto c = Expression::compile(constants, {"X"});
  EXPECT_EQ((*c)({1.0}), 1.0 + 100000.0 * 100001.0 / 2.0);
}
