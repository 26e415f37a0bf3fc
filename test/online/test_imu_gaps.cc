#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "common/calibration/calibration_inputs.h"
#include "common/math/rotation.h"
#include "replay/replay.h"
#include "sim/simulator.h"
#include "temp_dir.h"

namespace giocal {
namespace {

/// The field preset cut to two laps (about 260 s): long straights after the gap to restart on.
CalibrationInputs twoLapsOfTheField(std::uint64_t seed) {
  sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/field.yaml");
  cfg.segments.resize(2 + 2 * 4);  // stationary, speed-up, two laps of four segments
  test::TempDir dir;
  sim::writeDataset(sim::simulate(cfg, seed), dir.path() + "/data");
  return loadCalibrationInputs(dir.path() + "/data");
}

CalibrationInputs withImuGap(CalibrationInputs in, double t0, double length) {
  in.imu.erase(std::remove_if(in.imu.begin(), in.imu.end(),
                              [&](const ImuSample& s) { return s.t > t0 && s.t < t0 + length; }),
               in.imu.end());
  return in;
}

TEST(ImuGaps, BothEstimatorsBridgeOrRestartAndStayWithinTwiceTheCleanError) {
  const CalibrationInputs clean = twoLapsOfTheField(41);
  for (const char* estimator : {"ekf", "fgo"}) {
    const CalibrationRun ref = replayInputs(clean, {estimator, {}, {}}, nullptr);
    const CalibrationError e0 = calibrationError(ref.final(), clean.truth->calib);
    const Eigen::Matrix<double, 8, 1> sd0 = ref.final().sigma();
    // In the first turn, and on the second straight.
    for (const auto& [place, gap] : std::vector<std::pair<double, double>>{
             {80.0, 1.0}, {80.0, 10.0}, {80.0, 30.0}, {100.0, 1.0}, {100.0, 10.0}, {100.0, 30.0}}) {
      const double t0 = clean.imu.front().t + place;
      SCOPED_TRACE(std::string(estimator) + " gap " + std::to_string(gap) + " s at +" +
                   std::to_string(place) + " s");
      const CalibrationInputs in = withImuGap(clean, t0, gap);
      const CalibrationRun run = replayInputs(in, {estimator, {}, {}}, nullptr);
      // 1 s is bridged (calibration.max_imu_bridge_s), longer gaps restart.
      const bool restart = gap > CalibrationOptions().max_imu_bridge_s;
      EXPECT_EQ(run.counter(Counter::kImuGaps), 1);
      EXPECT_EQ(run.counter(Counter::kImuRestarts), restart ? 1 : 0);
      EXPECT_EQ(run.status, "ok");
      EXPECT_EQ(restart,
                std::any_of(run.warnings.begin(), run.warnings.end(), [](const std::string& w) {
                  return w.find("longer than calibration.max_imu_bridge_s") != std::string::npos;
                }));
      const CalibrationError e = calibrationError(run.final(), in.truth->calib);
      // Within twice the clean run's error, or its sigma where that error happens to be tiny.
      const auto near = [](double err, double err0, double sd) {
        return std::abs(err) <= 2.0 * std::max(std::abs(err0), sd);
      };
      EXPECT_TRUE(near(e.s_v, e0.s_v, sd0[0])) << e.s_v << " " << e0.s_v;
      EXPECT_TRUE(near(e.s_w, e0.s_w, sd0[1])) << e.s_w << " " << e0.s_w;
      EXPECT_TRUE(near(e.p_b_m.x(), e0.p_b_m.x(), sd0[2])) << e.p_b_m.x() << " " << e0.p_b_m.x();
      EXPECT_TRUE(near(e.p_b_m.y(), e0.p_b_m.y(), sd0[3])) << e.p_b_m.y() << " " << e0.p_b_m.y();
      for (int k = 0; k < 3; ++k) {
        EXPECT_TRUE(near(e.rpy[k] * kRadToDeg, e0.rpy[k] * kRadToDeg, sd0[5 + k]))
            << k << " " << e.rpy[k] * kRadToDeg << " " << e0.rpy[k] * kRadToDeg;
      }
      EXPECT_LT(e.nees7, 2.0 * e0.nees7 + 14.0);
    }
  }
}

TEST(ImuGaps, BridgedOrWhereNoRestartIsPossibleAPartialStatusWithTheLastCalibration) {
  // The paper preset circles after 70 s: no straight metre to find a heading on again.
  const sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml");
  test::TempDir dir;
  sim::writeDataset(sim::simulate(cfg, 42), dir.path() + "/data");
  const CalibrationInputs clean = loadCalibrationInputs(dir.path() + "/data");
  const double t0 = clean.imu.front().t + 70.0;
  for (const char* estimator : {"ekf", "fgo"}) {
    // The same drive without the gap, cut where a restart-less run stops.
    CalibrationInputs cut = clean;
    while (!cut.imu.empty() && cut.imu.back().t > t0) cut.imu.pop_back();
    const double clean_nees =
        calibrationError(replayInputs(cut, {estimator, {}, {}}, nullptr).final(),
                         clean.truth->calib)
            .nees7;
    for (double gap : {1.0, 10.0, 30.0}) {
      SCOPED_TRACE(std::string(estimator) + " gap " + std::to_string(gap));
      const CalibrationInputs in = withImuGap(clean, t0, gap);
      const CalibrationRun run = replayInputs(in, {estimator, {}, {}}, nullptr);
      ASSERT_TRUE(run.latest);
      if (gap <= CalibrationOptions().max_imu_bridge_s) {  // bridged: the whole drive
        EXPECT_EQ(run.status, "ok");
        EXPECT_GT(run.final().t, t0 + 60.0);
      } else {
        EXPECT_EQ(run.status.rfind("partial: an IMU gap", 0), 0u) << run.status;
        EXPECT_LE(run.final().t, t0 + 1e-6);
      }
      // What it reports is as honest as the drive's (measured 0.6-1.0; the cut drive's near).
      EXPECT_LT(calibrationError(run.final(), in.truth->calib).nees7, 2.0 * clean_nees + 14.07);
    }
  }
}

TEST(ImuGaps, ShortGapsAreBridged) {
  const sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml");
  test::TempDir dir;
  sim::writeDataset(sim::simulate(cfg, 43), dir.path() + "/data");
  const CalibrationInputs in = loadCalibrationInputs(dir.path() + "/data");
  const CalibrationInputs gap = withImuGap(in, in.imu.front().t + 70.0, 0.95);
  for (const char* estimator : {"ekf", "fgo"}) {
    const CalibrationRun run = replayInputs(gap, {estimator, {}, {}}, nullptr);
    EXPECT_EQ(run.counter(Counter::kImuGaps), 1) << estimator;
    EXPECT_EQ(run.counter(Counter::kImuRestarts), 0) << estimator;
    EXPECT_EQ(run.status, "ok");
    // The bridged run is as consistent as the same drive without the gap (a single seed's NEES
    // against a fixed bound passes or fails by luck; the EKF's paper-preset yaw sigma is known
    // too small: measured 22.4 with the gap on this seed).
    const double clean_nees =
        calibrationError(replayInputs(in, {estimator, {}, {}}, nullptr).final(), in.truth->calib)
            .nees7;
    EXPECT_LT(calibrationError(run.final(), in.truth->calib).nees7, 1.5 * clean_nees + 2.0)
        << estimator << ": the drive without the gap " << clean_nees;
  }
}

}  // namespace
}  // namespace giocal
