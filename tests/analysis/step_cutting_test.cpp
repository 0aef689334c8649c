// DEFI_LIST_INST/ECHEC: SUBD_METHODE='AUTO' (the cut from the residuals' extrapolation,
// against the formulas of step_cutting.hpp evaluated by hand) and SUBD_PAS_MINI, on the
// stiffening bar whose full step fails with few iterations allowed.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "analysis/step_cutting.hpp"
#include "stiffening_bar.hpp"

using namespace aster;
using analysis::automaticCut;

namespace {

struct CutRecorder : analysis::NewtonObserver {
  struct Cut {
    double t0, t1;
    int parts, level;
  };
  std::vector<Cut> cuts;
  std::vector<std::pair<double, double>> steps;
  void stepStarted(double t0, double t1) override { steps.push_back({t0, t1}); }
  void stepCut(double t0, double t1, int parts, int level, const std::string&) override {
    cuts.push_back({t0, t1, parts, level});
  }
};

}  // namespace

// Fewer than 7 residuals (iterations 0 to 5): no extrapolation, 4 equal sub-steps.
TEST(AutomaticCut, TooFewIterationsGiveFourEqualSubSteps) {
  const auto cut = automaticCut({1, 0.5, 0.25, 0.125, 0.06, 0.03}, 1e-6, 5);
  EXPECT_FALSE(cut.extrapolated);
  EXPECT_EQ(cut.parts, 4);
  EXPECT_DOUBLE_EQ(cut.firstFraction, 0.25);
}

// A residual that falls (halved at each of 11 iterations): 4 sub-steps, the first 1/7 of
// the step (24 / ((3 4 + 1)^2 - 1) = 24 / 168), the others 2/7.
TEST(AutomaticCut, AFallingResidualGivesAShortFirstSubStep) {
  std::vector<double> r;
  for (int i = 0; i <= 10; ++i) r.push_back(std::pow(0.5, i));
  const auto cut = automaticCut(r, 1e-6, 10);
  EXPECT_TRUE(cut.extrapolated);
  EXPECT_EQ(cut.parts, 4);
  EXPECT_DOUBLE_EQ(cut.firstFraction, 1.0 / 7);
  const auto ends = analysis::subStepEnds(2.0, 9.0, cut);
  ASSERT_EQ(ends.size(), 4u);
  EXPECT_DOUBLE_EQ(ends[0], 3.0);
  EXPECT_DOUBLE_EQ(ends[1], 5.0);
  EXPECT_DOUBLE_EQ(ends[2], 7.0);
  EXPECT_EQ(ends[3], 9.0);
}

// A residual that grows but stays below the criterion (the step failed for another reason).
// As 1.02^i from 1e-8 (criterion 1e-6, ITER_GLOB_MAXI = 10): the points lie on
// i = a + b log r, b = 1 / log 1.02 = 50.498; the criterion's iteration N = b log(100) =
// 232.6, r = 0.48485 e^((N - 10) / b) = 39.8, n = (sqrt(1 + 24 / r) - 1) / 3 = 0.09 < 2:
// 2 equal sub-steps.
TEST(AutomaticCut, AResidualGrowingBelowTheCriterionGivesTwoSubSteps) {
  std::vector<double> r;
  for (int i = 0; i <= 10; ++i) r.push_back(1e-8 * std::pow(1.02, i));
  const auto cut = automaticCut(r, 1e-6, 10);
  EXPECT_TRUE(cut.extrapolated);
  EXPECT_EQ(cut.parts, 2);
  EXPECT_DOUBLE_EQ(cut.firstFraction, 0.5);
}

// Growing as 1.001^i from 1e-6 e^-0.01201 (b = 1 / log 1.001 = 1000.5): N = 0.01201 b =
// 12.016 >= 1.2 ITER_GLOB_MAXI, r = 0.48485 e^((N - 10) / b) = 0.48583, n = 2.033: 2
// sub-steps, the first r of the step.
TEST(AutomaticCut, TheFirstFractionFromTheExtrapolatedIteration) {
  std::vector<double> r;
  for (int i = 0; i <= 10; ++i) r.push_back(1e-6 * std::exp(-0.01201) * std::pow(1.001, i));
  const auto cut = automaticCut(r, 1e-6, 10);
  const double b = 1 / std::log(1.001);
  const double N = 0.01201 * b;
  const double fraction = 0.48485 * std::exp((N - 10) / b);
  EXPECT_NEAR(fraction, 0.48583, 1e-5);
  EXPECT_TRUE(cut.extrapolated);
  EXPECT_EQ(cut.parts, 2);
  EXPECT_NEAR(cut.firstFraction, fraction, 1e-10);
}

// The bar pulled to P = 20 in one step with ITER_GLOB_MAXI = 7 fails (it needs 10); AUTO
// cuts it from the 8 residuals into a first sub-step of 1/7 and three of 2/7, which converge
// to the closed-form stretch.
TEST(AutomaticCut, TheBarConvergesAfterAnAutomaticCut) {
  analysis::NewtonSettings settings;
  settings.resiGlobRela = 1e-10;
  settings.iterGlobMaxi = 7;
  settings.subdAuto = true;
  CutRecorder rec;
  const auto run = test_support::pullBar(20, settings, true, &rec);
  ASSERT_TRUE(run.converged) << run.error;
  const double u = test_support::stretchOf(20) - 1;
  EXPECT_NEAR(run.u, u, 1e-8 * u);
  ASSERT_GE(rec.cuts.size(), 1u);
  EXPECT_EQ(rec.cuts[0].parts, 4);
  ASSERT_GE(rec.steps.size(), 2u);
  EXPECT_DOUBLE_EQ(rec.steps[1].second, 1.0 / 7);
}

// SUBD_PAS_MINI = 0.3 with SUBD_PAS = 4: the failed step [0, 1] would be cut into sub-steps
// of 0.25: the computation stops and says why.
TEST(AutomaticCut, NoSubStepBelowSubdPasMini) {
  analysis::NewtonSettings settings;
  settings.resiGlobRela = 1e-10;
  settings.iterGlobMaxi = 7;
  settings.subdPasMini = 0.3;
  const auto run = test_support::pullBar(20, settings, true);
  ASSERT_FALSE(run.converged);
  EXPECT_NE(run.error.find("would make a sub-step of 2.500E-01, below SUBD_PAS_MINI = 3.000E-01"), std::string::npos)
      << run.error;
  EXPECT_EQ(run.statistics.cuts, 0);
  // With AUTO too: its first sub-step would be 1/7.
  settings.subdAuto = true;
  settings.subdPasMini = 0.2;
  const auto automatic = test_support::pullBar(20, settings, true);
  ASSERT_FALSE(automatic.converged);
  EXPECT_NE(automatic.error.find("below SUBD_PAS_MINI = 2.000E-01"), std::string::npos) << automatic.error;
}

// AUTO has no level limit: a step that never converges (ITER_GLOB_MAXI = 1, too few
// residuals to extrapolate: 4 equal sub-steps each time) is cut until its sub-steps would
// fall below the round-off of the instants (1e-12 of the span 1: 0.25^20 = 9.1e-13 after
// 19 cuts), and the computation stops there.
TEST(AutomaticCut, WithoutSubdPasMiniTheCuttingStopsAtTheRoundOffOfTheInstants) {
  analysis::NewtonSettings settings;
  settings.resiGlobRela = 1e-300;
  settings.iterGlobMaxi = 1;
  settings.subdAuto = true;
  const auto run = test_support::pullBar(20, settings, true);
  ASSERT_FALSE(run.converged);
  EXPECT_NE(run.error.find("at the round-off of the instants"), std::string::npos) << run.error;
  EXPECT_EQ(run.statistics.cuts, 19);
}
