// The deleted residual from a solve with the factor equals the innovation test of a solve
// without it (linear factors), and a factor that alone decides a variable is not tested.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <memory>

#include "common/models/prior_model.h"
#include "common/models/random_walk_model.h"
#include "fgo/predicted_residual.h"

namespace giocal {
namespace {

StateKey x(int k) { return atEpoch(state::kP, k); }

std::shared_ptr<PriorModel> prior(const StateKey& key, const Eigen::Vector3d& mean, double sigma) {
  return std::make_shared<PriorModel>(std::vector<StateBlock>{vectorBlock(key)}, mean,
                                      Eigen::Matrix3d::Identity() * sigma * sigma);
}

const Eigen::Vector3d kP2(1.9, 0.4, 3.7);

SlidingWindow chain(bool with_p2) {
  SlidingWindow w;
  for (int k = 0; k < 3; ++k) w.addVariable(vectorBlock(x(k)), Eigen::Vector3d::Zero());
  w.addFactor({prior(x(0), Eigen::Vector3d(1, 2, 3), 0.5), {x(0)}, 0.0, "p0"});
  w.addFactor({std::make_shared<RandomWalkModel>(state::kP, 3, 0.3), {x(0), x(1)}, 0.0, "rw"});
  w.addFactor({std::make_shared<RandomWalkModel>(state::kP, 3, 0.2), {x(1), x(2)}, 0.0, "rw"});
  if (with_p2) w.addFactor({prior(x(2), kP2, 0.4), {x(2)}, 0.0, "p2"});
  return w;
}

TEST(PredictedResidual, EqualsTheInnovationTestOfTheWindowWithoutTheFactor) {
  SlidingWindow with = chain(true), without = chain(false);
  ASSERT_TRUE(with.solve(50, 1e-14).usable);
  ASSERT_TRUE(without.solve(50, 1e-14).usable);
  const Eigen::Vector3d innovation = kP2 - without.value(x(2));
  const Eigen::Matrix3d S = Eigen::Matrix3d::Identity() * 0.16 + without.covariance({x(2)});
  const double expected = innovation.dot(S.ldlt().solve(innovation));
  const Factor& p2 = with.factors().back();
  ASSERT_EQ(p2.tag, "p2");
  const PredictedResidual got = predictedResidual(with, p2);
  EXPECT_EQ(got.dof, 3);
  EXPECT_NEAR(got.chi2, expected, 1e-6 * expected);
  // The solved residual alone is smaller: the factor pulled the solution toward itself.
  const Eigen::Vector3d solved = (kP2 - with.value(x(2))) / 0.4;
  EXPECT_LT(solved.squaredNorm(), 0.5 * expected);
}

TEST(PredictedResidual, AFactorThatAloneDecidesItsVariableIsNotTested) {
  SlidingWindow w = chain(true);
  const StateKey lonely = state::kPbg;
  w.addVariable(vectorBlock(lonely), Eigen::Vector3d::Zero());
  w.addFactor({prior(lonely, Eigen::Vector3d(5, 5, 5), 0.1), {lonely}, 0.0, "alone"});
  ASSERT_TRUE(w.solve(50, 1e-14).usable);
  const PredictedResidual got = predictedResidual(w, w.factors().back());
  EXPECT_EQ(got.dof, 0);
  EXPECT_EQ(got.chi2, 0.0);
}

TEST(PredictedResidual, TheCovarianceAlongColumnsIsTheirQuadraticForm) {
  SlidingWindow w = chain(true);
  ASSERT_TRUE(w.solve(50, 1e-14).usable);
  Eigen::MatrixXd G(6, 2);
  G << 1, 0, 2, -1, 0, 3, 0.5, 0, -1, 1, 0, 2;
  const Eigen::MatrixXd C = w.covariance({x(2), x(0)});
  EXPECT_LT((w.covarianceAlong({x(2), x(0)}, G) - G.transpose() * C * G).norm(), 1e-12);
  EXPECT_THROW(w.covarianceAlong({x(2)}, G), std::invalid_argument);
}

}  // namespace
}  // namespace giocal
