// RECH_LINEAIRE: the search itself on functionals whose roots are known by hand, and the
// driver on a bar whose stiffening response makes full Newton steps overshoot.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "stiffening_bar.hpp"
#include "analysis/convergence_table.hpp"
#include "analysis/line_search.hpp"
#include "analysis/static_nonlinear.hpp"
#include "core/error.hpp"

using namespace aster;
using analysis::LineSearchSettings;
using test_support::BarRun;
using test_support::pullBar;

namespace {

// f(rho) = (rho - 0.6)(rho + 2) = rho^2 + 1.4 rho - 1.2: f(0) = -1.2, f(1) = 1.2.
double quadratic(double rho) { return (rho - 0.6) * (rho + 2); }

}  // namespace

// CORDE: the secant through (0, -1.2) and (1, 1.2) gives rho = 0.5, f(0.5) = -0.25; the
// secant through (1, 1.2) and (0.5, -0.25) gives rho = 1 - 1.2 (0.5 / 1.45) = 0.586207,
// |f| = 0.0351 < 0.1 |f(0)| = 0.12 with RESI_LINE_RELA = 0.1: three trials.
TEST(LineSearch, CordeTakesTheSecantStepsOfAQuadratic) {
  LineSearchSettings s;
  std::vector<double> tried;
  auto f = [&](double rho, double& value) {
    tried.push_back(rho);
    value = quadratic(rho);
    return true;
  };
  const auto out = analysis::lineSearch(s, quadratic(0), f);
  ASSERT_EQ(tried.size(), 3u);
  EXPECT_EQ(tried[0], 1.0);
  EXPECT_DOUBLE_EQ(tried[1], 0.5);
  const double secant = 1 - 1.2 * 0.5 / 1.45;
  EXPECT_NEAR(tried[2], secant, 1e-15);
  EXPECT_TRUE(out.converged);
  EXPECT_EQ(out.trials, 3);
  EXPECT_NEAR(out.rho, secant, 1e-15);
  EXPECT_NEAR(out.f, quadratic(secant), 1e-15);
}

// A tighter RESI_LINE_RELA and ITER_LINE_MAXI = 1: two trials, then the one of smallest |f| (0.5).
TEST(LineSearch, CordeKeepsTheBestTrialWhenItStops) {
  LineSearchSettings s;
  s.resiLineRela = 1e-6;
  s.iterLineMaxi = 1;
  int calls = 0;
  auto f = [&](double rho, double& value) {
    ++calls;
    value = quadratic(rho);
    return true;
  };
  const auto out = analysis::lineSearch(s, quadratic(0), f);
  EXPECT_EQ(calls, 2);
  EXPECT_FALSE(out.converged);
  EXPECT_DOUBLE_EQ(out.rho, 0.5);
}

// The secant step is brought back into [RHO_MIN, RHO_MAX]: f(rho) = rho - 50 (root beyond RHO_MAX = 10).
TEST(LineSearch, CordeStaysWithinRhoMax) {
  LineSearchSettings s;
  std::vector<double> tried;
  auto f = [&](double rho, double& value) {
    tried.push_back(rho);
    value = rho - 50;
    return true;
  };
  const auto out = analysis::lineSearch(s, -50, f);
  ASSERT_GE(tried.size(), 2u);
  EXPECT_EQ(tried[1], 10.0);
  EXPECT_EQ(out.rho, 10.0);
}

TEST(LineSearch, AdmissibleRhoKeepsOutOfTheExclusionInterval) {
  LineSearchSettings s;
  s.rhoMin = -1;
  s.rhoExcl = 0.05;
  EXPECT_EQ(analysis::admissibleRho(s, 0.01), 0.05);
  EXPECT_EQ(analysis::admissibleRho(s, -0.01), -0.05);
  EXPECT_EQ(analysis::admissibleRho(s, -3), -1.0);
  EXPECT_EQ(analysis::admissibleRho(s, 20), 10.0);
}

// MIXTE on f(rho) = rho - 5: f(1) < 0, so rho goes to 3, then 9 (a sign change: [3, 9]);
// |f(9)| = 4 did not fall below |f(3)| = 2: the middle, 6; then the secant of (9, 4) and
// (6, 1): rho = 5, the root. Five trials: ITER_LINE_MAXI = 4.
TEST(LineSearch, MixteBracketsThenTakesTheSecant) {
  LineSearchSettings s;
  s.method = LineSearchSettings::Method::Mixte;
  s.iterLineMaxi = 4;
  std::vector<double> tried;
  auto f = [&](double rho, double& value) {
    tried.push_back(rho);
    value = rho - 5;
    return true;
  };
  const auto out = analysis::lineSearch(s, -5, f);
  ASSERT_EQ(tried.size(), 5u);
  EXPECT_EQ(tried[0], 1.0);
  EXPECT_EQ(tried[1], 3.0);
  EXPECT_EQ(tried[2], 9.0);
  EXPECT_EQ(tried[3], 6.0);
  EXPECT_DOUBLE_EQ(tried[4], 5.0);
  EXPECT_TRUE(out.converged);
  EXPECT_DOUBLE_EQ(out.rho, 5.0);
}

// MIXTE on the quadratic: bracket [0, 1] at once, secant of (0, -1.2) and (1, 1.2): 0.5,
// then the secant of (1, 1.2) and (0.5, -0.25) within [0.5, 1]: 0.586207, converged.
TEST(LineSearch, MixteOnTheQuadratic) {
  LineSearchSettings s;
  s.method = LineSearchSettings::Method::Mixte;
  std::vector<double> tried;
  auto f = [&](double rho, double& value) {
    tried.push_back(rho);
    value = quadratic(rho);
    return true;
  };
  const auto out = analysis::lineSearch(s, quadratic(0), f);
  ASSERT_EQ(tried.size(), 3u);
  EXPECT_DOUBLE_EQ(tried[1], 0.5);
  EXPECT_NEAR(out.rho, 1 - 1.2 * 0.5 / 1.45, 1e-15);
}

// A trial that cannot be evaluated stops the search with the best rho before it.
TEST(LineSearch, AFailedTrialStopsTheSearch) {
  LineSearchSettings s;
  s.resiLineRela = 1e-9;
  auto f = [&](double rho, double& value) {
    value = quadratic(rho);
    return rho > 0.9;  // the second trial (0.5) fails
  };
  const auto out = analysis::lineSearch(s, quadratic(0), f);
  EXPECT_TRUE(out.failedTrial);
  EXPECT_EQ(out.trials, 1);
  EXPECT_EQ(out.rho, 1.0);
}

namespace {

analysis::NewtonSettings barSettings(bool lineSearch, int iterGlobMaxi) {
  analysis::NewtonSettings settings;
  settings.resiGlobRela = 1e-10;
  settings.iterGlobMaxi = iterGlobMaxi;
  settings.subdNiveau = 0;
  settings.lineSearch = lineSearch;
  return settings;
}

}  // namespace

// P = 20 E: plain Newton needs 10 corrections to RESI_GLOB_RELA = 1e-10, CORDE's line search
// 6 (a scalar model of the same iterations, u + rho du on l (l^2 - 1) / 2 = P, gives 9 and 6
// to 1e-6); both reach the closed-form stretch.
TEST(LineSearchDriver, ReachesConvergenceInFewerIterationsWhenNewtonOvershoots) {
  const double P = 20;
  const BarRun plain = pullBar(P, barSettings(false, 30));
  const BarRun searched = pullBar(P, barSettings(true, 30));
  ASSERT_TRUE(plain.converged);
  ASSERT_TRUE(searched.converged);
  const double u = test_support::stretchOf(P) - 1;
  EXPECT_NEAR(plain.u, u, 1e-8 * u);
  EXPECT_NEAR(searched.u, u, 1e-8 * u);
  EXPECT_LE(searched.iterations, plain.iterations - 3) << plain.iterations << " " << searched.iterations;
  // With ITER_GLOB_MAXI between the two counts, only the line search converges.
  const int maxi = searched.iterations;
  EXPECT_FALSE(pullBar(P, barSettings(false, maxi)).converged);
  EXPECT_TRUE(pullBar(P, barSettings(true, maxi)).converged);
}

// With RECH_LINEAIRE the table has code_aster's RECH. LINE. columns (trials, rho), blank
// for an iteration without a line search (the prediction, the converged one).
TEST(ConvergenceTable, LineSearchColumns) {
  analysis::ConvergenceTable table(false, true);
  analysis::NewtonIteration it;
  it.index = 0;
  it.rela = 1;
  it.maxi = 2;
  it.matrix = "TANGENTE";
  it.seconds = 0.5;
  testing::internal::CaptureStdout();
  table.stepStarted(0.0, 1.0);
  table.iterationDone(it);
  it.index = 1;
  it.lineSearchTrials = 3;
  it.rho = 0.586207;
  table.iterationDone(it);
  EXPECT_EQ(testing::internal::GetCapturedStdout(),
            "  Instant 1.000000E+00\n"
            "    iter  RESI_GLOB_RELA   RESI_GLOB_MAXI   RL iter  RL rho       matrix      time (s)   \n"
            "       0  1.000000E+00     2.00E+00                               TANGENTE    5.00E-01   \n"
            "       1  1.000000E+00     2.00E+00               3  5.8621E-01   TANGENTE    5.00E-01   \n");
}
