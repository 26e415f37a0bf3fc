#include <gtest/gtest.h>

#include "calibration_checks.h"
#include "common/calibration/calibration_inputs.h"
#include "common/math/rotation.h"
#include "common/online/run_sink.h"
#include "replay/replay.h"
#include "sim/simulator.h"
#include "temp_dir.h"

namespace giocal {
namespace {

TEST(FgoCalibrator, CalibratesThePaperSimulation) {
  const sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml");
  test::TempDir dir;
  sim::writeDataset(sim::simulate(cfg, 606), dir.path() + "/data");
  const CalibrationInputs in = loadCalibrationInputs(dir.path() + "/data");
  RunRecording recording;
  const CalibrationRun run = replayInputs(in, {"fgo", CalibrationOptions{}, {}}, &recording);
  ASSERT_TRUE(run.latest);
  // Each observable state within 4 of its reported sigma, that sigma under a share of the
  // prior's: an estimator that does nothing fails it (test/calibration_checks.h).
  test::expectWithinSigmaAndInformed(run.final(), in);
  EXPECT_GT(run.fixRate(), 0.9);
  EXPECT_TRUE(run.final().cov.allFinite());
  const CalibrationPrior& prior = in.description.initial_calibration;
  EXPECT_EQ(run.final().calib.p_b_m.z(), prior.mean.p_b_m.z());  // held
  EXPECT_FALSE(recording.trajectory_samples.empty());
  EXPECT_EQ(recording.history.size(), static_cast<size_t>(run.gnss_epochs));
}

}  // namespace
}  // namespace giocal
