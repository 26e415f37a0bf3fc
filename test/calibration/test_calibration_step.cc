#include <gtest/gtest.h>

#include <cmath>

#include "common/calibration/calibration_run.h"
#include "common/math/so3.h"

namespace giocal {
namespace {

CalibrationEstimate estimateWithSigmas() {
  CalibrationEstimate e;
  e.calib.s_v = 0.01;
  e.calib.s_w = -0.02;
  e.calib.p_b_m = {0.3, -0.2, 0.15};
  e.calib.q_b_m = Eigen::Quaterniond(expSO3(Eigen::Vector3d(0.02, -0.03, 0.05)));
  const double sd[8] = {0.002, 0.004, 0.05, 0.1, 0.5, 0.01, 0.02, 0.04};
  for (int k = 0; k < 8; ++k) e.cov(k, k) = sd[k] * sd[k];
  return e;
}

TEST(CalibrationStep, IsTheMoveInTheSigmasBeforeOverTheObservableStates) {
  const CalibrationEstimate before = estimateWithSigmas();
  CalibrationEstimate after = before;
  after.cov *= 1e-4;  // the sigmas after do not enter
  EXPECT_NEAR(calibrationStepChi2(before, after), 0.0, 1e-12);
  after.calib.s_v += 3 * 0.002;      // 3 sigma
  after.calib.p_b_m.y() += 2 * 0.1;  // 2 sigma
  after.calib.p_b_m.z() += 10.0;     // p_b_m.z is not among the seven
  after.calib.q_b_m = after.calib.q_b_m * Eigen::Quaterniond(expSO3(Eigen::Vector3d(0, 0, 0.08)));
  EXPECT_NEAR(calibrationStepChi2(before, after), 9.0 + 4.0 + 4.0, 1e-6);  // yaw 2 sigma
  // Correlation counts: a move along a correlated pair's shared direction is cheaper.
  CalibrationEstimate correlated = before;
  correlated.cov(0, 1) = correlated.cov(1, 0) = 0.9 * 0.002 * 0.004;
  after = before;
  after.calib.s_v += 0.002;
  after.calib.s_w += 0.004;
  EXPECT_NEAR(calibrationStepChi2(correlated, after), 2.0 / 1.9, 1e-6);
}

}  // namespace
}  // namespace giocal
