// A number with its first and second derivatives with respect to N variables
// (second-order forward automatic differentiation): the mortar integrals are
// written once, in Jet arithmetic, and give their exact gradient and Hessian.
//
//   Jet::variable(value, i): the i-th variable (gradient e_i, Hessian 0);
//   Jet::constant(value):    a number that depends on none.
// Every operation applies the chain rule to second order: for f(a),
//   (f a).g = f'(a) a.g,   (f a).h = f'(a) a.h + f''(a) a.g a.g^T,
// and for a product (ab).h = a b.h + b a.h + a.g b.g^T + b.g a.g^T.
//
// Quantities defined implicitly, r(s, q) = 0 (a projection), are computed in
// doubles first, then refined by two Newton steps s <- s - r / r_s taken in
// Jet arithmetic (newtonRefine): the error of Newton's iterate is quadratic in
// the previous one, so from a value exact to round-off, one step makes the
// first derivatives exact and a second one the second derivatives.
#pragma once
#include <cmath>

#include <Eigen/Core>

namespace aster::contact {

template <int N>
struct Jet {
  using Vector = Eigen::Matrix<double, N, 1>;
  using Matrix = Eigen::Matrix<double, N, N>;
  double v = 0;
  Vector g = Vector::Zero();
  Matrix h = Matrix::Zero();

  static Jet constant(double value) {
    Jet j;
    j.v = value;
    return j;
  }
  static Jet variable(double value, int i) {
    Jet j;
    j.v = value;
    j.g(i) = 1;
    return j;
  }
  // f(this) from f = f(v), f' and f''.
  Jet apply(double f, double df, double d2f) const {
    Jet r;
    r.v = f;
    r.g = df * g;
    r.h = df * h + d2f * (g * g.transpose());
    return r;
  }

  Jet& operator+=(const Jet& b) {
    v += b.v;
    g += b.g;
    h += b.h;
    return *this;
  }
  Jet& operator-=(const Jet& b) {
    v -= b.v;
    g -= b.g;
    h -= b.h;
    return *this;
  }
  Jet& operator*=(double s) {
    v *= s;
    g *= s;
    h *= s;
    return *this;
  }
  Jet& operator+=(double s) {
    v += s;
    return *this;
  }
};

template <int N>
Jet<N> operator+(Jet<N> a, const Jet<N>& b) { return a += b; }
template <int N>
Jet<N> operator-(Jet<N> a, const Jet<N>& b) { return a -= b; }
template <int N>
Jet<N> operator-(Jet<N> a) { return a *= -1.0; }
template <int N>
Jet<N> operator+(Jet<N> a, double s) { return a += s; }
template <int N>
Jet<N> operator+(double s, Jet<N> a) { return a += s; }
template <int N>
Jet<N> operator-(Jet<N> a, double s) { return a += -s; }
template <int N>
Jet<N> operator-(double s, const Jet<N>& a) { return -a + s; }
template <int N>
Jet<N> operator*(Jet<N> a, double s) { return a *= s; }
template <int N>
Jet<N> operator*(double s, Jet<N> a) { return a *= s; }

template <int N>
Jet<N> operator*(const Jet<N>& a, const Jet<N>& b) {
  Jet<N> r;
  r.v = a.v * b.v;
  r.g = a.v * b.g + b.v * a.g;
  const typename Jet<N>::Matrix cross = a.g * b.g.transpose();
  r.h = a.v * b.h + b.v * a.h + cross + cross.transpose();
  return r;
}

// 1 / a: f' = -1/a^2, f'' = 2/a^3.
template <int N>
Jet<N> inverse(const Jet<N>& a) {
  const double i = 1.0 / a.v;
  return a.apply(i, -i * i, 2 * i * i * i);
}
template <int N>
Jet<N> operator/(const Jet<N>& a, const Jet<N>& b) { return a * inverse(b); }
template <int N>
Jet<N> operator/(Jet<N> a, double s) { return a *= 1.0 / s; }

// sqrt(a), a > 0: f' = 1/(2 sqrt a), f'' = -1/(4 a sqrt a).
template <int N>
Jet<N> sqrt(const Jet<N>& a) {
  const double s = std::sqrt(a.v);
  return a.apply(s, 0.5 / s, -0.25 / (a.v * s));
}

// A 2D vector of Jets, with the few operations the mortar integrals need.
template <int N>
struct JetVec2 {
  Jet<N> x, y;
};
template <int N>
JetVec2<N> operator+(const JetVec2<N>& a, const JetVec2<N>& b) { return {a.x + b.x, a.y + b.y}; }
template <int N>
JetVec2<N> operator-(const JetVec2<N>& a, const JetVec2<N>& b) { return {a.x - b.x, a.y - b.y}; }
template <int N>
JetVec2<N> operator*(const Jet<N>& s, const JetVec2<N>& a) { return {s * a.x, s * a.y}; }
template <int N>
Jet<N> dot(const JetVec2<N>& a, const JetVec2<N>& b) { return a.x * b.x + a.y * b.y; }

// Two Newton steps s <- s - r(s) / r'(s) in Jet arithmetic from s0, a root of
// r found in doubles; `residual(s, r, dr)` sets r(s) and r'(s) (as Jets).
template <int N, class F>
Jet<N> newtonRefine(double s0, F&& residual) {
  Jet<N> s = Jet<N>::constant(s0);
  for (int k = 0; k < 2; ++k) {
    Jet<N> r, dr;
    residual(s, r, dr);
    s = s - r / dr;
  }
  return s;
}

}  // namespace aster::contact
