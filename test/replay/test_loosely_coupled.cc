// The LC scheme: both estimators calibrate from giocal rtk's position solutions.
#include <gtest/gtest.h>

#include <iostream>
#include <map>
#include <string>

#include "common/gnss/pos_reader.h"
#include "common/gnss/rtk_job.h"
#include "replay/replay.h"
#include "sim/simulator.h"
#include "temp_dir.h"

namespace giocal {
namespace {

constexpr double kNees7Bound95 = 14.07;   // chi-square, 7 degrees of freedom, 95 %
constexpr double kNees7Bound999 = 24.32;  // and 99.9 %: one run beyond it is a defect

/// A simulated drive in `dir` with giocal rtk's solution of it as its position solutions.
CalibrationInputs withRtkPositions(const sim::SimConfig& cfg, std::uint64_t seed,
                                   const test::TempDir& dir) {
  sim::writeDataset(sim::simulate(cfg, seed), dir.file("data"));
  CalibrationInputs in = loadCalibrationInputs(dir.file("data"));
  RtkJob rtk;
  rtk.rover = dir.file("data/rover.obs");
  rtk.base = dir.file("data/base.obs");
  rtk.nav = {dir.file("data/nav.rnx")};
  rtk.out = dir.file("rtk.pos");
  runRtk(rtk);
  in.positions = readPosFile(rtk.out);
  return in;
}

TEST(LooselyCoupled, BothEstimatorsCalibrateFromRtkPositionsThroughTheLeverArm) {
  sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/field.yaml");
  cfg.segments.resize(2 + 2 * 4);  // two laps, open sky and a few trees
  test::TempDir dir;
  CalibrationInputs in = withRtkPositions(cfg, 71, dir);
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
    EXPECT_LT(e.nees7, kNees7Bound999);  // one seed (consistency over ten: below)
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
    EXPECT_LT(e.nees7, kNees7Bound999);
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

// Consistency of the LC scheme over ten seeds never used while developing: both estimators on
// giocal rtk's solutions of three field laps each. A consistent estimator's NEES7 is under its
// 95 % bound with probability 0.95, so at least 8 of 10 runs (probability 0.99) must be.
TEST(LooselyCoupled, BothEstimatorsAreConsistentOverTenSeeds) {
  sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/field.yaml");
  cfg.segments.resize(2 + 4 * 3);  // the start and 3 of the 10 laps
  CalibrationOptions lc;
  lc.loosely_coupled = true;
  std::map<std::string, std::pair<int, std::string>> under;  // estimator -> (count, NEES list)
  for (std::uint64_t seed = 3601; seed <= 3610; ++seed) {
    test::TempDir dir;
    const CalibrationInputs in = withRtkPositions(cfg, seed, dir);
    for (const char* estimator : {"ekf", "fgo"}) {
      const CalibrationRun run = replayInputs(in, {estimator, lc, {}}, nullptr);
      const double n = calibrationError(run.final(), in.truth->calib).nees7;
      under[estimator].first += n < kNees7Bound95;
      under[estimator].second += " " + std::to_string(n);
    }
  }
  for (const auto& [estimator, result] : under) {
    std::cout << estimator << " LC NEES7 of seeds 3601-3610:" << result.second << "\n";
    EXPECT_GE(result.first, 8) << estimator << " NEES7 of seeds 3601-3610:" << result.second;
  }
}

}  // namespace
}  // namespace giocal
