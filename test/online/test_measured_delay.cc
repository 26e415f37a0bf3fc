// The odometer's delay measured on a dataset's logs before calibrating, and taken out of its
// stamps when asked (calibration.apply_odometer_delay_*; off by default).
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace giocal
