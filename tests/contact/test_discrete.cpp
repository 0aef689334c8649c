// DISCRETE node terms (assembled from the gap, checked by hand) and the
// active-set update rules.
#include <gtest/gtest.h>

#include "contact/discrete.hpp"
#include "core/error.hpp"

using namespace aster::contact;

TEST(Discrete, ActiveNodeTermsOnAFlatMaster) {
  // Master (2,0) -> (-1,0), n = (0,1); slave at (0.5,h): g = h, dg = (0,1,0,-1/2,0,-1/2).
  const double h = -0.01, lambda = -3.0;
  const NodeGap g = nodeToSegmentGap(Eigen::Vector2d(0.5, h), Segment::seg2({2, 0}, {-1, 0}));
  const DiscreteNodeTerms t = discreteNodeTerms(g, lambda, true);
  Eigen::VectorXd dg(6);
  dg << 0, 1, 0, -0.5, 0, -0.5;
  // Force on the slave = -lambda n = (0, 3): R_u = lambda dg (F_ext moved to the left side).
  EXPECT_NEAR((Eigen::VectorXd(t.residualU) - lambda * dg).norm(), 0, 1e-14);
  EXPECT_NEAR(t.residualLambda, h, 1e-15);
  EXPECT_NEAR((Eigen::VectorXd(t.tangentULambda) - dg).norm(), 0, 1e-14);
  EXPECT_NEAR((Eigen::MatrixXd(t.tangentUU) - lambda * Eigen::MatrixXd(g.hessian)).norm(), 0, 1e-14);
  EXPECT_EQ(t.tangentLambdaLambda, 0.0);
  const DiscreteNodeTerms off = discreteNodeTerms(g, lambda, false);
  EXPECT_EQ(Eigen::VectorXd(off.residualU).norm(), 0.0);
  EXPECT_EQ(off.residualLambda, lambda);
  EXPECT_EQ(off.tangentLambdaLambda, 1.0);
}

TEST(Discrete, ActiveSetActivatesPenetrationsFirst) {
  std::vector<bool> active = {false, false, true, true};
  const std::vector<double> gaps = {-0.1, 0.2, 0.0, 0.0};
  const std::vector<double> lambdas = {0.0, 0.0, 5.0, -1.0};
  const ActiveSetChange c = updateActiveSet(gaps, lambdas, active);
  EXPECT_EQ(c.activated, 1);
  EXPECT_EQ(c.released, 0);  // tension waits until no penetration is left
  EXPECT_EQ(active, (std::vector<bool>{true, false, true, true}));
}

TEST(Discrete, ActiveSetReleasesTheMostTensileNode) {
  std::vector<bool> active = {true, true, true, false};
  const std::vector<double> gaps = {0.0, 0.0, 0.0, 0.3};
  const std::vector<double> lambdas = {2.0, 7.0, -1.0, 0.0};
  ActiveSetChange c = updateActiveSet(gaps, lambdas, active);
  EXPECT_EQ(c.released, 1);
  EXPECT_EQ(active, (std::vector<bool>{true, false, true, false}));
  ActiveSetOptions all;
  all.releaseAllAtOnce = true;
  active = {true, true, true, false};
  c = updateActiveSet(gaps, lambdas, active, all);
  EXPECT_EQ(c.released, 2);
  EXPECT_EQ(active, (std::vector<bool>{false, false, true, false}));
  // Converged: nothing penetrates, nothing pulls.
  c = updateActiveSet(gaps, {0.0, 0.0, -1.0, 0.0}, active, all);
  EXPECT_FALSE(c.changed());
  std::vector<bool> wrong = {true};
  EXPECT_THROW(updateActiveSet(gaps, lambdas, wrong), aster::Error);
}

TEST(Discrete, TolerancesDelayChanges) {
  std::vector<bool> active = {false, true};
  ActiveSetOptions o;
  o.gapTolerance = 1e-6;
  o.multiplierTolerance = 1e-8;
  const ActiveSetChange c = updateActiveSet({-1e-7, 0.0}, {0.0, 1e-9}, active, o);
  EXPECT_FALSE(c.changed());
}

TEST(Discrete, PenalisedActiveNodeTerms) {
  // The same node, penalised with stiffness k: R_lambda = g - lambda / k,
  // K_lambdalambda = -1 / k, the displacement terms unchanged; lambda = k g
  // makes R_lambda vanish.
  const double h = -0.01, lambda = -3.0, k = 200.0;
  const NodeGap g = nodeToSegmentGap(Eigen::Vector2d(0.5, h), Segment::seg2({2, 0}, {-1, 0}));
  const DiscreteNodeTerms exact = discreteNodeTerms(g, lambda, true);
  const DiscreteNodeTerms t = discreteNodeTerms(g, lambda, true, k);
  EXPECT_NEAR(t.residualLambda, h - lambda / k, 1e-15);
  EXPECT_EQ(t.tangentLambdaLambda, -1 / k);
  EXPECT_EQ((Eigen::VectorXd(t.residualU) - Eigen::VectorXd(exact.residualU)).norm(), 0.0);
  EXPECT_EQ((Eigen::VectorXd(t.tangentULambda) - Eigen::VectorXd(exact.tangentULambda)).norm(), 0.0);
  EXPECT_NEAR(discreteNodeTerms(g, k * h, true, k).residualLambda, 0.0, 1e-17);
  // Inactive: lambda = 0 whatever k.
  EXPECT_EQ(discreteNodeTerms(g, lambda, false, k).residualLambda, lambda);
  EXPECT_THROW(discreteNodeTerms(g, lambda, true, -1.0), aster::Error);
}
