// The odometer's delay measured on a dataset's logs before calibrating, and taken out of its
// stamps when asked (calibration.apply_odometer_delay_*; off by default); named by the run with
// the offset to set, and estimated as a state on request.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/calibration/calibration_inputs.h"
#include "replay/measured_delay.h"
#include "replay/replay.h"
#include "sim/simulator.h"
#include "temp_dir.h"

namespace giocal {
namespace {

// Two field laps whose wheel stamps are 50 ms late: measured within 3 sigma (under 10 ms);
// taken out, the calibration measures what is left as nothing; with the default, untouched.
TEST(MeasuredDelay, ALateOdometerIsMeasuredOnTheLogsAndTakenOutWhenAsked) {
  test::TempDir dir;
  sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/field.yaml");
  cfg.segments.resize(2 + 4 * 2);
  cfg.odometer.delay_s = 0.05;
  sim::writeDataset(sim::simulate(cfg, 3301), dir.file("late"));
  DatasetFolder data = openDatasetFolder(dir.file("late"));
  const OdometerDelay d = measureOdometerDelay(data);
  ASSERT_TRUE(d.valid);
  EXPECT_LT(d.sigma_s, 0.01);
  EXPECT_NEAR(d.delay_s, 0.05, 3.0 * d.sigma_s);

  EXPECT_EQ(applyMeasuredOdometerDelay(data, CalibrationOptions{}), 0.0);  // off by default
  EXPECT_EQ(data.description.time_offsets.odometer, 0.0);
  CalibrationOptions asked;
  asked.apply_odometer_delay_sigma = 0.01;
  const double applied = applyMeasuredOdometerDelay(data, asked);
  EXPECT_EQ(applied, d.delay_s);
  EXPECT_EQ(data.description.time_offsets.odometer, -d.delay_s);
  ReplayJob job;
  job.estimator = "ekf";
  const CalibrationRun run = replayFolder(data, job, nullptr);
  ASSERT_TRUE(run.odometer_delay.valid);
  EXPECT_NEAR(run.odometer_delay.delay_s, 0.0, 3.0 * run.odometer_delay.sigma_s);
  // Not when the delay is to be estimated as a state.
  DatasetFolder again = openDatasetFolder(dir.file("late"));
  asked.estimate_odometer_delay = true;
  EXPECT_EQ(applyMeasuredOdometerDelay(again, asked), 0.0);
}

// Without the offset in dataset.yaml, a field drive whose wheel stamps are 50 ms late says so and
// names the offset to set, within the sigma it claims (under 5 ms); with it set, nothing is said.
TEST(OnlineCalibrator, LateOdometerStampsAreNamedWithTheOffsetToSet) {
  test::TempDir dir;
  sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/field.yaml");
  cfg.odometer.delay_s = 0.05;
  cfg.segments.resize(2 + 4 * 6);  // the start and 6 of the 10 laps
  sim::writeDataset(sim::simulate(cfg, 73), dir.file("late"));
  ReplayJob job;
  job.estimator = "ekf";
  const CalibrationRun late = replayFolder(dir.file("late"), job, nullptr);
  ASSERT_TRUE(late.odometer_delay.valid);
  const double sigma = late.odometer_delay.sigma_s;
  EXPECT_LT(sigma, 0.005);
  EXPECT_NEAR(late.odometer_delay.delay_s, 0.05, 3.0 * sigma);
  const auto said = std::find_if(late.warnings.begin(), late.warnings.end(), [](auto& w) {
    return w.find("odometer's stamps are") != std::string::npos;
  });
  ASSERT_NE(said, late.warnings.end());
  EXPECT_NE(said->find("time_offsets: {odometer: -0.0"), std::string::npos) << *said;

  DatasetDescription d = readDatasetDescription(dir.file("late"));
  d.time_offsets.odometer = -0.05;
  writeDatasetDescription(d);
  const CalibrationRun fixed = replayFolder(dir.file("late"), job, nullptr);
  EXPECT_NEAR(fixed.odometer_delay.delay_s, 0.0, 3.0 * sigma);
  for (const std::string& w : fixed.warnings)
    EXPECT_EQ(w.find("odometer's stamps"), std::string::npos);
}

// With calibration.estimate_odometer_delay, both estimators estimate a 50 ms wheel delay of a field
// drive (6 of its 10 laps) within 3 sigma, a sigma under 4 ms, and the run neither asks for a time
// offset it has taken out nor finds the state at odds with the yaw rates; an on-time drive's is
// zero within its sigma. A speed-only odometer refuses the option (bench/odometer_delay.sh: 5 ms).
TEST(OnlineCalibrator, TheOdometerDelayIsEstimatedByBothEstimators) {
  test::TempDir dir;
  sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/field.yaml");
  cfg.segments.resize(2 + 4 * 6);  // the start and 6 of the 10 laps
  sim::writeDataset(sim::simulate(cfg, 207), dir.file("on_time"));
  cfg.odometer.delay_s = 0.05;
  sim::writeDataset(sim::simulate(cfg, 207), dir.file("late"));
  ReplayJob job;
  job.options.estimate_odometer_delay = true;
  for (const char* estimator : {"ekf", "fgo"}) {
    job.estimator = estimator;
    const CalibrationRun late = replayFolder(dir.file("late"), job, nullptr);
    const CalibrationEstimate& e = late.final();
    ASSERT_TRUE(std::isfinite(e.odometer_delay_s)) << estimator;
    EXPECT_LT(e.odometer_delay_sd_s, 0.004) << estimator;
    EXPECT_NEAR(e.odometer_delay_s, 0.05, 3.0 * e.odometer_delay_sd_s) << estimator;
    for (const std::string& w : late.warnings) {
      EXPECT_EQ(w.find("odometer's stamps"), std::string::npos) << estimator << ": " << w;
      EXPECT_EQ(w.find("disagrees"), std::string::npos) << estimator << ": " << w;
    }
  }
  job.estimator = "ekf";
  const CalibrationEstimate on_time = replayFolder(dir.file("on_time"), job, nullptr).final();
  EXPECT_NEAR(on_time.odometer_delay_s, 0.0, 3.0 * on_time.odometer_delay_sd_s);

  DatasetDescription d = readDatasetDescription(dir.file("late"));
  d.odom_noise.measures_yaw_rate = false;
  writeDatasetDescription(d);
  try {
    replayFolder(dir.file("late"), job, nullptr);
    ADD_FAILURE() << "a speed-only odometer's delay was estimated";
  } catch (const std::exception& ex) {
    EXPECT_NE(std::string(ex.what()).find("estimate_odometer_delay"), std::string::npos)
        << ex.what();
  }
}

}  // namespace
}  // namespace giocal
