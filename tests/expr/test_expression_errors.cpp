// Every compile-time and checked-evaluation error of the FORMULE compiler:
// the message names what went wrong, the 1-based column and what was expected.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "expr/expression.hpp"

using aster::expr::Expression;

namespace {

std::string compileError(const std::string& text, const std::vector<std::string>& params = {"X", "Y"}) {
  try {
    Expression::compile(text, params);
  } catch (const aster::Error& e) {
    return e.what();
  }
  return "no error for: " + text;
}

std::string evalError(const std::string& text, std::vector<double> args,
                      const std::vector<std::string>& params = {"X", "Y"}) {
  auto e = Expression::compile(text, params);
  try {
    e->evaluateChecked(args.data());
  } catch (const aster::Error& err) {
    return err.what();
  }
  return "no error for: " + text;
}

}  // namespace

#define EXPECT_CONTAINS(text, part) \
  EXPECT_NE(std::string(text).find(part), std::string::npos) << "message: " << (text)

TEST(ExpressionErrors, UnexpectedTokens) {
  EXPECT_CONTAINS(compileError("(X + Y) * 20 - Y)"), "unexpected ')' at column 17 (no '(' to close)");
  EXPECT_CONTAINS(compileError("X Y"), "unexpected 'Y' at column 3: expected an operator");
  EXPECT_CONTAINS(compileError("X * / Y"), "unexpected '/' at column 5: expected a number, a name or '('");
  EXPECT_CONTAINS(compileError("()"), "unexpected ')' at column 2");
  EXPECT_CONTAINS(compileError("sin(X,)"), "unexpected ')' at column 7");
  EXPECT_CONTAINS(compileError("max(X Y)"), "unexpected 'Y' at column 7: expected ')' to close 'max(' at column 4");
  EXPECT_CONTAINS(compileError("2 3"), "unexpected '3' at column 3");
}

TEST(ExpressionErrors, Unterminated) {
  EXPECT_CONTAINS(compileError("X +"), "unterminated expression: an operand is expected after '+' at column 3");
  EXPECT_CONTAINS(compileError("X **"), "unterminated expression: an operand is expected after '**' at column 3");
  EXPECT_CONTAINS(compileError("(X + Y"), "unterminated expression: missing ')' to close '(' at column 1");
  EXPECT_CONTAINS(compileError("1 + sin(X"), "unterminated expression: missing ')' to close 'sin(' at column 8");
  EXPECT_CONTAINS(compileError("-"), "unterminated expression");
  EXPECT_CONTAINS(compileError(""), "empty expression");
  EXPECT_CONTAINS(compileError("   "), "empty expression");
}

TEST(ExpressionErrors, Names) {
  EXPECT_CONTAINS(compileError("X + Z"), "unknown name 'Z' at column 5 (parameters: X, Y)");
  EXPECT_CONTAINS(compileError("x", {}), "unknown name 'x' at column 1 (parameters: none)");
  EXPECT_CONTAINS(compileError("2*foo(X)"), "unknown function 'foo' at column 3 (functions: sin, cos");
  EXPECT_CONTAINS(compileError("X(2)"), "'X' at column 1 is a parameter, not a function");
  EXPECT_CONTAINS(compileError("1 + sin"), "function 'sin' at column 5 must be called with arguments");
  EXPECT_CONTAINS(compileError("1", {"X", "X"}), "parameter 'X' is listed twice");
  EXPECT_CONTAINS(compileError("1", {"2X"}), "parameter name '2X' is not a valid name");
  EXPECT_CONTAINS(compileError("1", {"sin"}), "parameter name 'sin' is reserved");
}

TEST(ExpressionErrors, FunctionArity) {
  EXPECT_CONTAINS(compileError("1+atan2(X)"), "function 'atan2' takes 2 arguments, got 1 at column 3");
  EXPECT_CONTAINS(compileError("sin(X, Y)"), "function 'sin' takes 1 argument, got 2 at column 1");
  EXPECT_CONTAINS(compileError("cos()"), "function 'cos' takes 1 argument, got 0 at column 1");
  EXPECT_CONTAINS(compileError("min(X)"), "function 'min' takes at least 2 arguments, got 1 at column 1");
  EXPECT_CONTAINS(compileError("max()"), "function 'max' takes at least 2 arguments, got 0 at column 1");
}

TEST(ExpressionErrors, Lexer) {
  EXPECT_CONTAINS(compileError("X $ Y"), "unexpected character '$' at column 3");
  EXPECT_CONTAINS(compileError("X ^ 2"), "unexpected character '^' at column 3 (powers are written **)");
  EXPECT_CONTAINS(compileError("X // 2"), "operator '//' (floor division) is not supported at column 3");
  EXPECT_CONTAINS(compileError("X % 2"), "operator '%' is not supported at column 3");
  EXPECT_CONTAINS(compileError("1e"), "malformed number '1e' at column 1");
  EXPECT_CONTAINS(compileError("X+1.2.3"), "malformed number '1.2.3' at column 3");
  EXPECT_CONTAINS(compileError("2X"), "malformed number '2X' at column 1");
  EXPECT_CONTAINS(compileError("1e999"), "number '1e999' at column 1 is too large");
  EXPECT_CONTAINS(compileError("X . Y"), "unexpected character '.' at column 3");
}

TEST(ExpressionErrors, MessagesQuoteTheText) {
  EXPECT_CONTAINS(compileError("X + Z"), "in \"X + Z\"");
  // Long generated formulas are quoted around the column only.
  std::string longText = "X";
  for (int i = 0; i < 40; ++i) longText += " + X";
  longText += " + Q";
  const std::string message = compileError(longText);
  EXPECT_CONTAINS(message, "unknown name 'Q' at column 165");
  EXPECT_CONTAINS(message, "...");
  EXPECT_CONTAINS(message, "+ Q\"");
  EXPECT_LT(message.size(), 200u);
  // Nesting is bounded instead of overflowing the parser's stack.
  EXPECT_CONTAINS(compileError(std::string(1000, '(') + "1" + std::string(1000, ')')),
                  "nested too deeply");
  // So are chains of signs and powers and nested calls, each a level of recursion.
  std::string powers = "X";
  for (int i = 0; i < 100000; ++i) powers += "**X";
  EXPECT_CONTAINS(compileError(powers), "nested too deeply at column 602 (more than 200 levels");
  EXPECT_CONTAINS(compileError(std::string(1000000, '-') + "X"), "nested too deeply at column 201");
  std::string calls;
  for (int i = 0; i < 100000; ++i) calls += "sin(";
  calls += "X" + std::string(100000, ')');
  EXPECT_CONTAINS(compileError(calls), "nested too deeply at column 804");
  // 200 levels are allowed.
  EXPECT_NO_THROW(Expression::compile(std::string(200, '-') + "X", {"X"}));
}

TEST(ExpressionErrors, CheckedEvaluation) {
  EXPECT_CONTAINS(evalError("2*log(X)", {-1, 0}),
                  "log of a negative number (log(-1)) at column 3 of \"2*log(X)\", with X = -1, Y = 0");
  EXPECT_CONTAINS(evalError("log10(X)", {0, 0}), "log10 of zero at column 1");
  EXPECT_CONTAINS(evalError("sqrt(X - Y)", {1, 5}), "sqrt of a negative number (sqrt(-4)) at column 1");
  EXPECT_CONTAINS(evalError("1 + X/Y", {1, 0}), "division by zero (1 / 0) at column 6");
  EXPECT_CONTAINS(evalError("X/Y", {0, 0}), "division by zero (0 / 0)");
  EXPECT_CONTAINS(evalError("X**Y", {-8, 0.5}),
                  "negative number raised to a non-integer power ((-8) ** 0.5) at column 2");
  EXPECT_CONTAINS(evalError("X**0.5", {-8, 0}), "negative number raised to a non-integer power");
  EXPECT_CONTAINS(evalError("X**-1", {0, 0}), "zero raised to a negative power (0 ** (-1))");
  EXPECT_CONTAINS(evalError("asin(X)", {2, 0}), "asin of 2, outside [-1, 1] at column 1");
  EXPECT_CONTAINS(evalError("acos(X)", {-1.5, 0}), "acos of -1.5, outside [-1, 1]");
  EXPECT_CONTAINS(evalError("exp(X)", {1000, 0}), "overflow or domain error in exp(1000)");
  EXPECT_CONTAINS(evalError("X*Y", {1e200, 1e200}), "overflow in 1e+200 * 1e+200");
  EXPECT_CONTAINS(evalError("X**2", {1e200, 0}), "overflow in power (1e+200 ** 2)");
  EXPECT_CONTAINS(evalError("X+Y", {std::nan(""), 0}), "parameter X = nan is not a finite number");
  // A constant failing operation is not folded away: the checked evaluation still reports it.
  EXPECT_CONTAINS(evalError("X + log(-1)", {1, 0}), "log of a negative number (log(-1)) at column 5");
  // The unchecked evaluation lets IEEE values through, as the hot loops want.
  auto e = Expression::compile("log(X)", {"X"});
  EXPECT_TRUE(std::isnan((*e)({-1.0})));
  const double ok = 4.0;
  EXPECT_EQ(Expression::compile("sqrt(X)", {"X"})->evaluateChecked(&ok), 2.0);
}

TEST(ExpressionErrors, ArgumentCount) {
  auto e = Expression::compile("X+Y", {"X", "Y"});
  EXPECT_THROW((*e)({1.0}), aster::Error);
}
