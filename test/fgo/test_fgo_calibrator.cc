#include <gtest/gtest.h>

#include "common/calibration/calibration_inputs.h"
#include "common/math/rotation.h"
#include "fgo/fgo_calibrator.h"
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
  const CalibrationRun run = runFgoCalibration(in, CalibrationOptions{});
  ASSERT_FALSE(run.history.empty());
  // Bounds the 20-seed Monte Carlo (bench/monte_carlo.cc, seeds 1-20, default window 30) stays
  // inside with margin: the worst seed there had 0.053 m, 0.37 deg roll, 0.28 deg pitch, 9.4 deg
  // yaw, 4.6e-3 and 5.0e-3 in the scales.
  const CalibrationError e = calibrationError(run.history.back(), in.truth->calib);
  EXPECT_LT(std::abs(e.p_b_m.x()), 0.1);
  EXPECT_LT(std::abs(e.p_b_m.y()), 0.1);
  EXPECT_LT(std::abs(e.rpy.x()), 0.8 * kDegToRad);
  EXPECT_LT(std::abs(e.rpy.y()), 0.8 * kDegToRad);
  EXPECT_LT(std::abs(e.rpy.z()), 15.0 * kDegToRad);
  EXPECT_LT(std::abs(e.s_v), 0.01);
  EXPECT_LT(std::abs(e.s_w), 0.02);
  EXPECT_GT(run.fixRate(), 0.9);
  EXPECT_TRUE(run.history.back().cov.allFinite());
  const CalibrationPrior& prior = in.description.initial_calibration;
  EXPECT_EQ(run.history.back().calib.p_b_m.z(), prior.mean.p_b_m.z());  // held
  EXPECT_FALSE(run.trajectory.empty());
}

}  // namespace
}  // namespace giocal
