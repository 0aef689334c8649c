// Jet (second-order forward differentiation) against closed-form derivatives,
// and newtonRefine's derivatives of an implicit root against the implicit
// function theorem.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/jet.hpp"

using aster::contact::Jet;
using J = Jet<2>;

TEST(Jet, ProductQuotientAndSquareRootToSecondOrder) {
  // f(a, b) = a b / (a + b) + sqrt(a) at (a, b) = (2, 3).
  const double a = 2, b = 3;
  const J A = J::variable(a, 0), B = J::variable(b, 1);
  const J f = A * B / (A + B) + sqrt(A);
  const double s = a + b;
  EXPECT_NEAR(f.v, a * b / s + std::sqrt(a), 1e-15);
  // d/da = b^2/s^2 + 1/(2 sqrt a), d/db = a^2/s^2.
  EXPECT_NEAR(f.g(0), b * b / (s * s) + 0.5 / std::sqrt(a), 1e-15);
  EXPECT_NEAR(f.g(1), a * a / (s * s), 1e-15);
  // d2/da2 = -2 b^2/s^3 - 1/(4 a^1.5), d2/dadb = 2ab/s^3, d2/db2 = -2a^2/s^3.
  EXPECT_NEAR(f.h(0, 0), -2 * b * b / (s * s * s) - 0.25 / std::pow(a, 1.5), 1e-15);
  EXPECT_NEAR(f.h(0, 1), 2 * a * b / (s * s * s), 1e-15);
  EXPECT_NEAR(f.h(1, 0), 2 * a * b / (s * s * s), 1e-15);
  EXPECT_NEAR(f.h(1, 1), -2 * a * a / (s * s * s), 1e-15);
}

TEST(Jet, NewtonRefineGivesTheImplicitRootsDerivatives) {
  // s(p, q) solves s^3 + p s - q = 0; at (p, q) = (1, 2) the root is s = 1.
  // Implicit derivatives: r_s = 3 s^2 + p = 4, r_p = s = 1, r_q = -1;
  // s_p = -1/4, s_q = 1/4; second ones from
  // r_s s_ij + r_ss s_i s_j + r_si s_j + r_sj s_i + r_ij = 0 with r_ss = 6 s = 6,
  // r_sp = 1, r_sq = 0, r_pp = r_pq = r_qq = 0.
  const J p = J::variable(1, 0), q = J::variable(2, 1);
  const J s = aster::contact::newtonRefine<2>(1.0, [&](const J& x, J& r, J& dr) {
    r = x * x * x + p * x - q;
    dr = 3.0 * (x * x) + p;
  });
  const double sp = -0.25, sq = 0.25;
  EXPECT_NEAR(s.v, 1.0, 1e-15);
  EXPECT_NEAR(s.g(0), sp, 1e-15);
  EXPECT_NEAR(s.g(1), sq, 1e-15);
  EXPECT_NEAR(s.h(0, 0), -(6 * sp * sp + 2 * sp) / 4, 1e-14);
  EXPECT_NEAR(s.h(0, 1), -(6 * sp * sq + sq) / 4, 1e-14);
  EXPECT_NEAR(s.h(1, 1), -(6 * sq * sq) / 4, 1e-14);
}
