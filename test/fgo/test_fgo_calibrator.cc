#include <gtest/gtest.h>

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
  // Bounds the 20-seed Monte Carlo (bench/monte_carlo.cc, seeds 1-20, default window 30) stays
  // inside with margin: the worst seed there had 0.053 m, 0.37 deg roll, 0.28 deg pitch, 9.4 deg
  // yaw, 4.6e-3 and 5.0e-3 in the scales.
  const CalibrationError e = calibrationError(run.final(), in.truth->calib);
  EXPECT_LT(std::abs(e.p_b_m.x()), 0.1);
  EXPECT_LT(std::abs(e.p_b_m.y()), 0.1);
  EXPECT_LT(std::abs(e.rpy.x()), 0.8 * kDegToRad);
  EXPECT_LT(std::abs(e.rpy.y()), 0.8 * kDegToRad);
  EXPECT_LT(std::abs(e.rpy.z()), 15.0 * kDegToRad);
  EXPECT_LT(std::abs(e.s_v), 0.01);
  EXPECT_LT(std::abs(e.s_w), 0.02);
  EXPECT_GT(run.fixRate(), 0.9);
  EXPECT_TRUE(run.final().cov.allFinite());
  const CalibrationPrior& prior = in.description.initial_calibration;
  EXPECT_EQ(run.final().calib.p_b_m.z(), prior.mean.p_b_m.z());  // held
  EXPECT_FALSE(recording.trajectory_samples.empty());
  EXPECT_EQ(recording.history.size(), static_cast<size_t>(run.gnss_epochs));
}

}  // namespace
}  // namespace giocal
