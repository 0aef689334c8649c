// Forward-mode automatic differentiation numbers.
//   Dual1<N>: value and gradient with respect to N variables.
//   Dual2<N>: value, gradient and Hessian (full N x N, symmetric).
// Both support the operations and functions of FORMULE (expression.hpp), so a
// compiled expression evaluates with them unchanged: the manufactured loads get
// exact second derivatives of the displacement, never finite differences.
// No heap: sizes are compile-time, the default constructor leaves storage
// uninitialized (like double) so that evaluation stacks cost nothing to create.
#pragma once
#include <cmath>

namespace aster::expr {

// Every function below is written once here, for any dual D that provides:
//   D(double) (a constant), double v (the value),
//   D chain(f0, f1, f2): f(a) given f, f', f'' at a.v,
//   static D linear(c, ca, a, cb, b): c + ca*a + cb*b (value c is the full value),
//   static D chain2(a, b, f, fa, fb, faa, fab, fbb): f(a, b) given its partials.
// They are hidden friends: found by argument-dependent lookup only, so `sin(x)`
// picks std::sin for double and these for duals in the same template code.
template <class D>
struct DualMath {
  friend D operator+(const D& a) { return a; }
  friend D operator-(const D& a) { return a.chain(-a.v, -1.0, 0.0); }

  friend D operator+(const D& a, const D& b) { return D::linear(a.v + b.v, 1.0, a, 1.0, b); }
  friend D operator-(const D& a, const D& b) { return D::linear(a.v - b.v, 1.0, a, -1.0, b); }
  friend D operator*(const D& a, const D& b) {
    return D::chain2(a, b, a.v * b.v, b.v, a.v, 0.0, 1.0, 0.0);
  }
  friend D operator/(const D& a, const D& b) {
    const double q = a.v / b.v, r = 1.0 / b.v;
    // f = a/b: f_a = 1/b, f_b = -a/b^2, f_ab = -1/b^2, f_bb = 2a/b^3.
    return D::chain2(a, b, q, r, -q * r, 0.0, -r * r, 2.0 * q * r * r);
  }

  friend D operator+(const D& a, double c) { return a.chain(a.v + c, 1.0, 0.0); }
  friend D operator+(double c, const D& a) { return a.chain(c + a.v, 1.0, 0.0); }
  friend D operator-(const D& a, double c) { return a.chain(a.v - c, 1.0, 0.0); }
  friend D operator-(double c, const D& a) { return a.chain(c - a.v, -1.0, 0.0); }
  friend D operator*(const D& a, double c) { return a.chain(a.v * c, c, 0.0); }
  friend D operator*(double c, const D& a) { return a.chain(c * a.v, c, 0.0); }
  friend D operator/(const D& a, double c) { return a.chain(a.v / c, 1.0 / c, 0.0); }
  friend D operator/(double c, const D& a) {
    const double r = 1.0 / a.v;
    return a.chain(c * r, -c * r * r, 2.0 * c * r * r * r);
  }

  friend D& operator+=(D& a, const D& b) { return a = a + b; }
  friend D& operator-=(D& a, const D& b) { return a = a - b; }
  friend D& operator*=(D& a, const D& b) { return a = a * b; }
  friend D& operator/=(D& a, const D& b) { return a = a / b; }

  // Comparisons look at values only (min, max, branches).
  friend bool operator<(const D& a, const D& b) { return a.v < b.v; }
  friend bool operator>(const D& a, const D& b) { return a.v > b.v; }
  friend bool operator<=(const D& a, const D& b) { return a.v <= b.v; }
  friend bool operator>=(const D& a, const D& b) { return a.v >= b.v; }

  friend D sin(const D& a) {
    const double s = std::sin(a.v), c = std::cos(a.v);
    return a.chain(s, c, -s);
  }
  friend D cos(const D& a) {
    const double s = std::sin(a.v), c = std::cos(a.v);
    return a.chain(c, -s, -c);
  }
  friend D tan(const D& a) {
    const double t = std::tan(a.v), d = 1.0 + t * t;
    return a.chain(t, d, 2.0 * t * d);
  }
  friend D asin(const D& a) {
    const double w = 1.0 - a.v * a.v, r = 1.0 / std::sqrt(w);
    return a.chain(std::asin(a.v), r, a.v * r / w);
  }
  friend D acos(const D& a) {
    const double w = 1.0 - a.v * a.v, r = 1.0 / std::sqrt(w);
    return a.chain(std::acos(a.v), -r, -a.v * r / w);
  }
  friend D atan(const D& a) {
    const double r = 1.0 / (1.0 + a.v * a.v);
    return a.chain(std::atan(a.v), r, -2.0 * a.v * r * r);
  }
  friend D sinh(const D& a) {
    const double s = std::sinh(a.v), c = std::cosh(a.v);
    return a.chain(s, c, s);
  }
  friend D cosh(const D& a) {
    const double s = std::sinh(a.v), c = std::cosh(a.v);
    return a.chain(c, s, c);
  }
  friend D tanh(const D& a) {
    const double t = std::tanh(a.v), d = 1.0 - t * t;
    return a.chain(t, d, -2.0 * t * d);
  }
  friend D exp(const D& a) {
    const double e = std::exp(a.v);
    return a.chain(e, e, e);
  }
  friend D log(const D& a) {
    const double r = 1.0 / a.v;
    return a.chain(std::log(a.v), r, -r * r);
  }
  friend D log10(const D& a) {
    const double r = 1.0 / (a.v * std::log(10.0));
    return a.chain(std::log10(a.v), r, -r / a.v);
  }
  friend D sqrt(const D& a) {
    const double s = std::sqrt(a.v);
    return a.chain(s, 0.5 / s, -0.25 / (s * a.v));
  }
  // Derivative sign(x), 0 at 0 (the symmetric choice, as sympy's sign).
  friend D abs(const D& a) {
    const double s = a.v > 0 ? 1.0 : (a.v < 0 ? -1.0 : 0.0);
    return a.chain(std::abs(a.v), s, 0.0);
  }

  // x**c, c real: f' = c x^(c-1), f'' = c (c-1) x^(c-2), written so that x = 0 with
  // c >= 2 and negative x with integer c both work (no division by x).
  friend D pow(const D& a, double c) {
    if (c == 0.0) return D(1.0);  // as Python: x**0 == 1 for every x
    if (c == 1.0) return a;
    const double f1 = c * std::pow(a.v, c - 1.0);
    const double f2 = c == 2.0 ? 2.0 : c * (c - 1.0) * std::pow(a.v, c - 2.0);
    return a.chain(std::pow(a.v, c), f1, f2);
  }
  // c**x = exp(x ln c).
  friend D pow(double c, const D& a) {
    const double f = std::pow(c, a.v), l = std::log(c);
    return a.chain(f, f * l, f * l * l);
  }
  // a**b with both variable: a > 0 is required for real derivatives in b.
  friend D pow(const D& a, const D& b) {
    const double f = std::pow(a.v, b.v), l = std::log(a.v);
    const double am1 = std::pow(a.v, b.v - 1.0);
    const double am2 = std::pow(a.v, b.v - 2.0);
    return D::chain2(a, b, f, b.v * am1, f * l, b.v * (b.v - 1.0) * am2, am1 * (1.0 + b.v * l),
                     f * l * l);
  }

  // atan2(y, x): d/dy = x/r2, d/dx = -y/r2, second partials over r2^2.
  friend D atan2(const D& y, const D& x) {
    const double r2 = x.v * x.v + y.v * y.v, q = 1.0 / (r2 * r2);
    return D::chain2(y, x, std::atan2(y.v, x.v), x.v / r2, -y.v / r2, -2.0 * x.v * y.v * q,
                     (y.v * y.v - x.v * x.v) * q, 2.0 * x.v * y.v * q);
  }
  friend D atan2(const D& y, double x) { return atan2(y, D(x)); }
  friend D atan2(double y, const D& x) { return atan2(D(y), x); }

  // Python semantics: the first of equal candidates wins, nan only if first.
  friend D min(const D& a, const D& b) { return b.v < a.v ? b : a; }
  friend D max(const D& a, const D& b) { return b.v > a.v ? b : a; }
};

template <int N>
struct Dual1 : DualMath<Dual1<N>> {
  static_assert(N >= 1, "Dual1 needs at least one variable");
  double v;
  double d[N];

  Dual1() = default;  // uninitialized, as double
  Dual1(double value) : v(value) {  // NOLINT: implicit, a constant mixes with duals
    for (int i = 0; i < N; ++i) d[i] = 0.0;
  }
  // The i-th independent variable at the given value.
  static Dual1 variable(double value, int i) {
    Dual1 r(value);
    r.d[i] = 1.0;
    return r;
  }

  Dual1 chain(double f0, double f1, double /*f2*/) const {
    Dual1 r;
    r.v = f0;
    for (int i = 0; i < N; ++i) r.d[i] = f1 * d[i];
    return r;
  }
  static Dual1 linear(double value, double ca, const Dual1& a, double cb, const Dual1& b) {
    Dual1 r;
    r.v = value;
    for (int i = 0; i < N; ++i) r.d[i] = ca * a.d[i] + cb * b.d[i];
    return r;
  }
  static Dual1 chain2(const Dual1& a, const Dual1& b, double f, double fa, double fb, double,
                      double, double) {
    return linear(f, fa, a, fb, b);
  }
};

template <int N>
struct Dual2 : DualMath<Dual2<N>> {
  static_assert(N >= 1, "Dual2 needs at least one variable");
  double v;
  double g[N];     // gradient
  double h[N][N];  // Hessian, symmetric

  Dual2() = default;  // uninitialized, as double
  Dual2(double value) : v(value) {  // NOLINT: implicit, a constant mixes with duals
    for (int i = 0; i < N; ++i) {
      g[i] = 0.0;
      for (int j = 0; j < N; ++j) h[i][j] = 0.0;
    }
  }
  static Dual2 variable(double value, int i) {
    Dual2 r(value);
    r.g[i] = 1.0;
    return r;
  }

  Dual2 chain(double f0, double f1, double f2) const {
    Dual2 r;
    r.v = f0;
    for (int i = 0; i < N; ++i) r.g[i] = f1 * g[i];
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) r.h[i][j] = f1 * h[i][j] + f2 * g[i] * g[j];
    return r;
  }
  static Dual2 linear(double value, double ca, const Dual2& a, double cb, const Dual2& b) {
    Dual2 r;
    r.v = value;
    for (int i = 0; i < N; ++i) r.g[i] = ca * a.g[i] + cb * b.g[i];
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) r.h[i][j] = ca * a.h[i][j] + cb * b.h[i][j];
    return r;
  }
  static Dual2 chain2(const Dual2& a, const Dual2& b, double f, double fa, double fb, double faa,
                      double fab, double fbb) {
    Dual2 r;
    r.v = f;
    for (int i = 0; i < N; ++i) r.g[i] = fa * a.g[i] + fb * b.g[i];
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j)
        r.h[i][j] = fa * a.h[i][j] + fb * b.h[i][j] + faa * a.g[i] * a.g[j] +
                    fab * (a.g[i] * b.g[j] + b.g[i] * a.g[j]) + fbb * b.g[i] * b.g[j];
    return r;
  }
};

}  // namespace aster::expr
