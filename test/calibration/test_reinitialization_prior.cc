#include <gtest/gtest.h>

#include "common/calibration/reinitialization_prior.h"

namespace giocal {
namespace {

DatasetDescription guessed() {
  DatasetDescription d;
  CalibrationPrior& p = d.initial_calibration;
  p.mean.s_v = 0.01;
  p.mean.p_b_m = Eigen::Vector3d(0.1, -0.2, 0.3);
  p.sd_s_v = p.sd_s_w = 0.02;
  p.sd_p_b_m = Eigen::Vector3d::Constant(0.5);
  p.sd_rpy_b_m = Eigen::Vector3d::Constant(5.0 * M_PI / 180.0);
  return d;
}

CalibrationEstimate estimateOf(const OdometerCalibration& c) {
  CalibrationEstimate e;
  e.calib = c;
  e.cov = Eigen::MatrixXd::Identity(8, 8) * 1e-6;
  return e;
}

TEST(ReinitializationPrior, AnEstimateNearTheGuessIsKeptAFarOneIsNot) {
  const DatasetDescription d = guessed();
  OdometerCalibration near = d.initial_calibration.mean;
  near.s_v += 0.05;                                                // 2.5 sigma
  near.p_b_m.x() += 1.4;                                           // 2.8 sigma
  near.q_b_m = Eigen::AngleAxisd(0.25, Eigen::Vector3d::UnitZ());  // 14.3 deg: 2.9 sigma
  const DatasetDescription kept = reinitializationPrior(d, estimateOf(near));
  EXPECT_DOUBLE_EQ(kept.initial_calibration.mean.s_v, near.s_v);
  EXPECT_DOUBLE_EQ(kept.initial_calibration.mean.p_b_m.x(), near.p_b_m.x());
  // The scales' sigmas stay at least the prior's, whatever the estimate claims.
  EXPECT_DOUBLE_EQ(kept.initial_calibration.sd_s_v, 0.02);

  // The factor graph's diverged estimate of docs/results.md: p_b_m.x 5597 m.
  for (int k = 0; k < 4; ++k) {
    OdometerCalibration far = near;
    if (k == 0) far.p_b_m.x() = 5597.0;
    if (k == 1) far.s_w = 0.07;                                                 // 3.5 sigma
    if (k == 2) far.q_b_m = Eigen::AngleAxisd(0.27, Eigen::Vector3d::UnitX());  // 3.1 sigma
    if (k == 3) far.p_b_m.z() = 1.9;                                            // 3.2 sigma
    SCOPED_TRACE(k);
    const DatasetDescription back = reinitializationPrior(d, estimateOf(far));
    EXPECT_DOUBLE_EQ(back.initial_calibration.mean.s_v, d.initial_calibration.mean.s_v);
    EXPECT_DOUBLE_EQ(back.initial_calibration.mean.p_b_m.x(), 0.1);
  }
}

}  // namespace
}  // namespace giocal
