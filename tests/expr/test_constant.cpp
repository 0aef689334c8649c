// DEFI_CONSTANTE's function: the same value at any abscissa, of any parameter.
#include <gtest/gtest.h>

#include <limits>

#include "expr/constant.hpp"
#include "expr/tabulated.hpp"

using namespace aster::expr;

TEST(Constant, SameValueAnywhere) {
  const Constant c(-2.75);
  EXPECT_EQ(c.parameters(), std::vector<std::string>{"TOUTPARA"});
  for (double x : {-1e300, -1.0, 0.0, 0.5, 1e300}) EXPECT_EQ(c.evaluate(&x), -2.75);
  EXPECT_EQ(c({3.0}), -2.75);
}

TEST(Constant, TakesAnyParameter) {
  const Constant c(1.0);
  EXPECT_TRUE(takesOnly(c, "INST"));
  EXPECT_TRUE(takesOnly(c, "X"));
  const Tabulated t("INST", {0.0, 1.0}, {0.0, 1.0});
  EXPECT_TRUE(takesOnly(t, "INST"));
  EXPECT_FALSE(takesOnly(t, "X"));
}

TEST(Constant, TabulatesToItsValue) {
  const auto t = tabulate(Constant(4.5), {0.0, 2.0, 3.0});
  EXPECT_EQ(t->ordinates(), (std::vector<double>{4.5, 4.5, 4.5}));
}
