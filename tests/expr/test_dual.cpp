// Dual numbers against hand-derived closed forms of first and second derivatives.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "expr/dual.hpp"
#include "expr/expression.hpp"

using aster::expr::Dual1;
using aster::expr::Dual2;
using D = Dual2<2>;

namespace {

constexpr double kTol = 1e-13;

// The inner argument a(x, y) = 0.3 x + 0.2 y^2 at (x, y): value, gradient, Hessian by hand.
struct Inner {
  double v, gx, gy, hxx, hxy, hyy;
};
Inner innerAt(double x, double y) { return {0.3 * x + 0.2 * y * y, 0.3, 0.4 * y, 0.0, 0.0, 0.4}; }

// f(a(x,y)): gradient f'(a) grad a, Hessian f'(a) H a + f''(a) grad a grad a^T, with the
// f' and f'' below written by hand from the usual derivative tables.
void checkUnary(const char* name, const std::function<D(const D&)>& f, double f0, double f1,
                double f2, double x, double y) {
  const D X = D::variable(x, 0), Y = D::variable(y, 1);
  const D r = f(0.3 * X + 0.2 * Y * Y);
  const Inner a = innerAt(x, y);
  SCOPED_TRACE(name);
  EXPECT_NEAR(r.v, f0, kTol * (1 + std::abs(f0)));
  EXPECT_NEAR(r.g[0], f1 * a.gx, kTol);
  EXPECT_NEAR(r.g[1], f1 * a.gy, kTol);
  EXPECT_NEAR(r.h[0][0], f1 * a.hxx + f2 * a.gx * a.gx, kTol);
  EXPECT_NEAR(r.h[0][1], f1 * a.hxy + f2 * a.gx * a.gy, kTol);
  EXPECT_NEAR(r.h[1][0], f1 * a.hxy + f2 * a.gy * a.gx, kTol);
  EXPECT_NEAR(r.h[1][1], f1 * a.hyy + f2 * a.gy * a.gy, kTol);
}

}  // namespace

TEST(Dual2, UnaryFunctionsAgainstDerivativeTables) {
  const double x = 0.7, y = 0.9;
  const double a = innerAt(x, y).v;  // 0.372
  const double c = std::cos(a), s = std::sin(a);
  checkUnary("sin", [](const D& u) { return sin(u); }, s, c, -s, x, y);
  checkUnary("cos", [](const D& u) { return cos(u); }, c, -s, -c, x, y);
  checkUnary("tan", [](const D& u) { return tan(u); }, s / c, 1 / (c * c), 2 * s / (c * c * c), x, y);
  const double w = 1 - a * a;
  checkUnary("asin", [](const D& u) { return asin(u); }, std::asin(a), 1 / std::sqrt(w),
             a / std::pow(w, 1.5), x, y);
  checkUnary("acos", [](const D& u) { return acos(u); }, std::acos(a), -1 / std::sqrt(w),
             -a / std::pow(w, 1.5), x, y);
  checkUnary("atan", [](const D& u) { return atan(u); }, std::atan(a), 1 / (1 + a * a),
             -2 * a / ((1 + a * a) * (1 + a * a)), x, y);
  checkUnary("sinh", [](const D& u) { return sinh(u); }, std::sinh(a), std::cosh(a), std::sinh(a), x, y);
  checkUnary("cosh", [](const D& u) { return cosh(u); }, std::cosh(a), std::sinh(a), std::cosh(a), x, y);
  const double ch = std::cosh(a);
  checkUnary("tanh", [](const D& u) { return tanh(u); }, std::tanh(a), 1 / (ch * ch),
             -2 * std::sinh(a) / (ch * ch * ch), x, y);
  checkUnary("exp", [](const D& u) { return exp(u); }, std::exp(a), std::exp(a), std::exp(a), x, y);
  checkUnary("log", [](const D& u) { return log(u); }, std::log(a), 1 / a, -1 / (a * a), x, y);
  checkUnary("log10", [](const D& u) { return log10(u); }, std::log10(a), 1 / (a * std::log(10.0)),
             -1 / (a * a * std::log(10.0)), x, y);
  checkUnary("sqrt", [](const D& u) { return sqrt(u); }, std::sqrt(a), 0.5 / std::sqrt(a),
             -0.25 / std::pow(a, 1.5), x, y);
  checkUnary("abs", [](const D& u) { return abs(-u); }, a, -1.0 * -1.0, 0.0, x, y);
  checkUnary("neg", [](const D& u) { return -u; }, -a, -1, 0, x, y);
  checkUnary("1/u", [](const D& u) { return 2.0 / u; }, 2 / a, -2 / (a * a), 4 / (a * a * a), x, y);
  checkUnary("u**2.5", [](const D& u) { return pow(u, 2.5); }, std::pow(a, 2.5), 2.5 * std::pow(a, 1.5),
             3.75 * std::sqrt(a), x, y);
  checkUnary("u**-3", [](const D& u) { return pow(u, -3.0); }, std::pow(a, -3), -3 * std::pow(a, -4),
             12 * std::pow(a, -5), x, y);
  checkUnary("3**u", [](const D& u) { return pow(3.0, u); }, std::pow(3, a),
             std::pow(3, a) * std::log(3.0), std::pow(3, a) * std::log(3.0) * std::log(3.0), x, y);
  checkUnary("u*u-u/4+1", [](const D& u) { return u * u - u / 4.0 + 1.0; }, a * a - a / 4 + 1,
             2 * a - 0.25, 2, x, y);
}

TEST(Dual2, BinaryFunctionsAgainstClosedForms) {
  // atan2(y, x) at (x, y) = (1, 2): r2 = 5; d/dy = x/r2, d/dx = -y/r2;
  // d2/dy2 = -2xy/r2^2, d2/dx2 = 2xy/r2^2, d2/dxdy = (y^2 - x^2)/r2^2.
  const D X = D::variable(1.0, 0), Y = D::variable(2.0, 1);
  D r = atan2(Y, X);
  EXPECT_NEAR(r.v, std::atan2(2.0, 1.0), kTol);
  EXPECT_NEAR(r.g[0], -2.0 / 5, kTol);
  EXPECT_NEAR(r.g[1], 1.0 / 5, kTol);
  EXPECT_NEAR(r.h[0][0], 4.0 / 25, kTol);
  EXPECT_NEAR(r.h[1][1], -4.0 / 25, kTol);
  EXPECT_NEAR(r.h[0][1], 3.0 / 25, kTol);
  EXPECT_NEAR(r.h[1][0], 3.0 / 25, kTol);

  // x**y at (1.5, 2.5): d/dx = y x^(y-1), d/dy = x^y ln x, d2/dx2 = y(y-1) x^(y-2),
  // d2/dxdy = x^(y-1) (1 + y ln x), d2/dy2 = x^y ln(x)^2.
  const double x = 1.5, y = 2.5, l = std::log(x);
  r = pow(D::variable(x, 0), D::variable(y, 1));
  EXPECT_NEAR(r.v, std::pow(x, y), kTol);
  EXPECT_NEAR(r.g[0], y * std::pow(x, y - 1), kTol);
  EXPECT_NEAR(r.g[1], std::pow(x, y) * l, kTol);
  EXPECT_NEAR(r.h[0][0], y * (y - 1) * std::pow(x, y - 2), kTol);
  EXPECT_NEAR(r.h[0][1], std::pow(x, y - 1) * (1 + y * l), kTol);
  EXPECT_NEAR(r.h[1][1], std::pow(x, y) * l * l, kTol);

  // x*y/(x+y) at (2, 3): d/dx = y^2/(x+y)^2, d2/dx2 = -2y^2/(x+y)^3, d2/dxdy = 2xy/(x+y)^3.
  const D A = D::variable(2.0, 0), B = D::variable(3.0, 1);
  r = A * B / (A + B);
  EXPECT_NEAR(r.v, 1.2, kTol);
  EXPECT_NEAR(r.g[0], 9.0 / 25, kTol);
  EXPECT_NEAR(r.g[1], 4.0 / 25, kTol);
  EXPECT_NEAR(r.h[0][0], -18.0 / 125, kTol);
  EXPECT_NEAR(r.h[1][1], -8.0 / 125, kTol);
  EXPECT_NEAR(r.h[0][1], 12.0 / 125, kTol);

  // min / max pass the selected operand's derivatives through.
  r = min(A * A, B);
  EXPECT_EQ(r.v, 3.0);
  EXPECT_EQ(r.g[1], 1.0);
  r = max(A * A, B);
  EXPECT_EQ(r.v, 4.0);
  EXPECT_EQ(r.g[0], 4.0);
  EXPECT_EQ(r.h[0][0], 2.0);
}

TEST(Dual2, PowerSpecialCases) {
  // Integer powers of a negative base and of zero keep exact derivatives.
  const Dual2<1> m = Dual2<1>::variable(-2.0, 0);
  Dual2<1> r = pow(m, 3.0);  // x^3: 3x^2, 6x
  EXPECT_EQ(r.v, -8.0);
  EXPECT_EQ(r.g[0], 12.0);
  EXPECT_EQ(r.h[0][0], -12.0);
  const Dual2<1> z = Dual2<1>::variable(0.0, 0);
  r = pow(z, 2.0);
  EXPECT_EQ(r.v, 0.0);
  EXPECT_EQ(r.g[0], 0.0);
  EXPECT_EQ(r.h[0][0], 2.0);
  r = pow(z, 0.0);  // Python: 0**0 == 1, a constant
  EXPECT_EQ(r.v, 1.0);
  EXPECT_EQ(r.g[0], 0.0);
}

TEST(Dual2, CompiledExpressionGivesTheHessianOfTheSsnp150Displacement) {
  // Uy = -0.05 (X-0.5)^2 (1+Y) - 0.01 Y: dUy/dX = -0.1 (X-0.5)(1+Y), dUy/dY = -0.05 (X-0.5)^2 - 0.01,
  // d2/dX2 = -0.1 (1+Y), d2/dXdY = -0.1, d2/dY2 = 0.
  auto uy = aster::expr::Expression::compile("-0.05*(X-0.5)**2*(1+Y) - 0.01*Y", {"X", "Y"});
  const double x = 0.8, y = 0.3;
  const D args[2] = {D::variable(x, 0), D::variable(y, 1)};
  const D r = uy->evaluateT(args);
  EXPECT_NEAR(r.g[0], -0.1 * (x - 0.5) * (1 + y), kTol);
  EXPECT_NEAR(r.g[1], -0.05 * (x - 0.5) * (x - 0.5) - 0.01, kTol);
  EXPECT_NEAR(r.h[0][0], -0.1 * (1 + y), kTol);
  EXPECT_NEAR(r.h[0][1], -0.1 * (x - 0.5), kTol);
  EXPECT_NEAR(r.h[1][1], 0.0, kTol);
}

TEST(Dual2, PowCallGivesTheDerivativesOfAPower) {
  // pow(10, t - 1.1) = exp((t - 1.1) ln 10): f' = f ln 10, f'' = f ln^2 10.
  auto e = aster::expr::Expression::compile("pow(10, INST-1.1)", {"INST"});
  const double t = 0.4, f = std::pow(10.0, t - 1.1), l = std::log(10.0);
  const Dual2<1> a[1] = {Dual2<1>::variable(t, 0)};
  Dual2<1> r = e->evaluateT(a);
  EXPECT_NEAR(r.v, f, kTol);
  EXPECT_NEAR(r.g[0], f * l, kTol);
  EXPECT_NEAR(r.h[0][0], f * l * l, kTol);
  // pow(X, Y) with both variable at (2, 3): f_x = y x^(y-1) = 12, f_y = x^y ln x = 8 ln 2,
  // f_xx = y (y-1) x^(y-2) = 12, f_xy = x^(y-1) (1 + y ln x) = 4 (1 + 3 ln 2), f_yy = 8 ln^2 2.
  auto xy = aster::expr::Expression::compile("pow(X, Y)", {"X", "Y"});
  const D b[2] = {D::variable(2.0, 0), D::variable(3.0, 1)};
  const D q = xy->evaluateT(b);
  const double l2 = std::log(2.0);
  EXPECT_NEAR(q.v, 8.0, kTol);
  EXPECT_NEAR(q.g[0], 12.0, kTol);
  EXPECT_NEAR(q.g[1], 8.0 * l2, kTol);
  EXPECT_NEAR(q.h[0][0], 12.0, kTol);
  EXPECT_NEAR(q.h[0][1], 4.0 * (1.0 + 3.0 * l2), kTol);
  EXPECT_NEAR(q.h[1][0], 4.0 * (1.0 + 3.0 * l2), kTol);
  EXPECT_NEAR(q.h[1][1], 8.0 * l2 * l2, kTol);
  // Against central differences of the compiled value.
  const double h = 1e-5;
  const double fd = ((*e)({t + h}) - (*e)({t - h})) / (2 * h);
  EXPECT_NEAR(r.g[0], fd, 1e-8 * std::abs(fd));
}

TEST(Dual1, GradientOnly) {
  // f = exp(x) sin(y) / x at (1, 0.5): df/dx = exp(x) sin(y) (x - 1)/x^2 = 0, df/dy = e cos(0.5).
  using E = Dual1<2>;
  const E x = E::variable(1.0, 0), y = E::variable(0.5, 1);
  const E r = exp(x) * sin(y) / x;
  EXPECT_NEAR(r.v, std::exp(1.0) * std::sin(0.5), kTol);
  EXPECT_NEAR(r.d[0], 0.0, kTol);
  EXPECT_NEAR(r.d[1], std::exp(1.0) * std::cos(0.5), kTol);
  auto e = aster::expr::Expression::compile("sqrt(X**2 + Y**2)", {"X", "Y"});
  const E a[2] = {E::variable(3.0, 0), E::variable(4.0, 1)};
  const E n = e->evaluateT(a);
  EXPECT_NEAR(n.v, 5.0, kTol);
  EXPECT_NEAR(n.d[0], 0.6, kTol);
  EXPECT_NEAR(n.d[1], 0.8, kTol);
}
