#include <gtest/gtest.h>

#include <cmath>

#include "common/io/dataset_description.h"
#include "common/math/rotation.h"
#include "replay/replay.h"
#include "sim/simulator.h"
#include "temp_dir.h"

namespace giocal {
namespace {

// A field drive (6 of its 10 laps, right turns, an IMU whose triads are misaligned) calibrated by
// both estimators with calibration.estimate_gyro_tilt: the gyro's tilt against the accelerometer
// comes out near the simulator's (within 4 sigma: the triads' 500 ppm scale errors, which no state
// models, moved it by up to 3 sigma on the development seeds), and the extrinsic yaw, which the
// tilt turned by several sigma before (docs/results.md), is within 3 sigma of the truth.
TEST(OnlineCalibrator, TheGyroTiltIsEstimatedByBothEstimators) {
  test::TempDir dir;
  sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/field.yaml");
  cfg.segments.resize(2 + 4 * 6);
  sim::writeDataset(sim::simulate(cfg, 208), dir.file("data"));
  const TruthCalibration truth = readTruthCalibration(dir.file("data") + "/truth_calib.yaml");
  ASSERT_TRUE(truth.gyro_tilt_deg.allFinite());
  ASSERT_GT(truth.gyro_tilt_deg.norm(), 0.01);  // degrees: something to find
  ReplayJob job;
  job.options.estimate_gyro_tilt = true;
  for (const char* estimator : {"ekf", "fgo"}) {
    job.estimator = estimator;
    const CalibrationEstimate e = replayFolder(dir.file("data"), job, nullptr).final();
    ASSERT_TRUE(e.gyro_tilt.allFinite()) << estimator;
    for (int k = 0; k < 2; ++k) {
      const double sd_deg = e.gyro_tilt_sd[k] * kRadToDeg;
      EXPECT_LT(sd_deg, 0.03) << estimator << " axis " << k;
      EXPECT_NEAR(e.gyro_tilt[k] * kRadToDeg, truth.gyro_tilt_deg[k], 4.0 * sd_deg)
          << estimator << " axis " << k;
    }
    const double yaw_error =
        rpyFromRotation((truth.calib.q_b_m.conjugate() * e.calib.q_b_m).toRotationMatrix())[2];
    EXPECT_LT(std::abs(yaw_error), 3.0 * e.sigma()[7]) << estimator;
  }
}

}  // namespace
}  // namespace giocal
