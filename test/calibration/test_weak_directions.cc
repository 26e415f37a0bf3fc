#include <gtest/gtest.h>

#include "common/calibration/initial_state.h"
#include "common/calibration/weak_directions.h"

namespace giocal {
namespace {

/// A final estimate at the prior's mean whose sigma is `f` times the prior's in every state.
CalibrationEstimate scaledPrior(const CalibrationPrior& prior, double f) {
  return CalibrationEstimate{0.0, prior.mean, f * f * priorCalibrationCovariance(prior)};
}

TEST(WeakDirections, NamesOnlyTheStatesTheDataBarelyInform) {
  const CalibrationPrior prior;
  EXPECT_TRUE(weakDirections(scaledPrior(prior, 0.1), prior).empty());

  // Yaw at half its prior sigma (the paper preset's EKF ends near 2.4 deg of 5 deg).
  CalibrationEstimate e = scaledPrior(prior, 0.1);
  const int yaw = calib_index::kTheta + 2;
  e.cov(yaw, yaw) = std::pow(0.5 * prior.sd_rpy_b_m.z(), 2);
  const std::vector<std::string> w = weakDirections(e, prior);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("yaw of q_b_m is weakly observed"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("2.5 deg against the prior's 5 deg"), std::string::npos) << w[0];

  // p_b_m.z kept at its prior (held under planar motion) is not a finding.
  e = scaledPrior(prior, 0.1);
  const int z = calib_index::kP + 2;
  e.cov(z, z) = std::pow(prior.sd_p_b_m.z(), 2);
  EXPECT_TRUE(weakDirections(e, prior).empty());

  // Nothing estimated at all: every observable state is named, p_b_m.z is not.
  EXPECT_EQ(weakDirections(scaledPrior(prior, 1.0), prior).size(), 7u);
}

}  // namespace
}  // namespace giocal
