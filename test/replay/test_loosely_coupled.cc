// The LC scheme: both estimators calibrate from giocal rtk's position solutions.
#include <gtest/gtest.h>

#include "common/gnss/pos_reader.h"
#include "common/gnss/rtk_job.h"
#include "replay/replay.h"
#include "sim/simulator.h"
#include "temp_dir.h"

namespace giocal {
namespace {

TEST(LooselyCoupled, BothEstimatorsCalibrateFromRtkPositionsThroughTheLeverArm) {
  sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/field.yaml");
  cfg.segments.resize(2 + 2 * 4);  // two laps, open sky and a few trees
  test::TempDir dir;
  sim::writeDataset(sim::simulate(cfg, 71), dir.file("data"));
  CalibrationInputs in = loadCalibrationInputs(dir.file("data"));
  RtkJob rtk;
  rtk.rover = dir.file("data/rover.obs");
  rtk.base = dir.file("data/base.obs");
  rtk.nav = {dir.file("data/nav.rnx")};
  rtk.out = dir.file("rtk.pos");
  runRtk(rtk);
  in.positions = readPosFile(rtk.out);
  ASSERT_GT(in.positions.size(), 200u);
  CalibrationOptions lc;
  lc.loosely_coupled = true;
  for (const char* estimator : {"ekf", "fgo"}) {
    SCOPED_TRACE(estimator);
    const CalibrationRun run = replayInputs(in, {estimator, lc, {}}, nullptr);
    EXPECT_GT(run.gnss_epochs, 0.8 * static_cast<double>(in.rover.epochs.size()));
    // Raw GNSS beside the solutions: the rows judged are the positions (a rejected fix was once
    // counted against zero double-difference rows, and "suspect" followed).
    EXPECT_EQ(run.status, "ok") << run.status;
    const CalibrationError e = calibrationError(run.final(), in.truth->calib);
    const Eigen::Matrix<double, 8, 1> sd = run.final().sigma();
    // The positions inform the calibration (sigmas far below the prior's) and the sigma covers
    // the error.
    EXPECT_LT(sd[0], 0.2 * in.description.initial_calibration.sd_s_v);
    EXPECT_LT(sd[3], 0.2 * in.description.initial_calibration.sd_p_b_m.y());
    EXPECT_LT(std::abs(e.s_v), 4.0 * sd[0]) << e.s_v;
    EXPECT_LT(e.p_b_m.head<2>().norm(), 4.0 * sd.segment<2>(2).norm()) << e.p_b_m.transpose();
    EXPECT_LT(e.nees7, 30.0);
  }
  // Without raw GNSS (an imported bag's gnss.pos): the solutions are the epochs, and the
  // initial heading comes from them.
  CalibrationInputs only = in;
  only.description.rover_obs.clear();
  only.description.base_obs.clear();
  only.rover.epochs.clear();
  only.base.epochs.clear();
  for (const char* estimator : {"ekf", "fgo"}) {
    SCOPED_TRACE(estimator);
    const CalibrationRun run = replayInputs(only, {estimator, lc, {}}, nullptr);
    EXPECT_GT(run.gnss_epochs, 0.8 * static_cast<double>(in.positions.size()));
    const CalibrationError e = calibrationError(run.final(), in.truth->calib);
    const Eigen::Matrix<double, 8, 1> sd = run.final().sigma();
    EXPECT_LT(std::abs(e.s_v), 4.0 * sd[0]) << e.s_v;
    EXPECT_LT(e.nees7, 30.0);
  }
  // Without any position solution LC has no GNSS to start from: a clear error, not a silent run.
  in.positions.clear();
  try {
    replayInputs(in, {"ekf", lc, {}}, nullptr);
    ADD_FAILURE() << "expected no initial state";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no position solution"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace giocal
