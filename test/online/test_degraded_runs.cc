// A degraded run says why: an odometer gap, a GNSS outage and rover epochs without a base are
// counted and named once each; the factor graph, like the EKF, leaves out odometer intervals and
// samples of wheel slip instead of letting them pull the scales, and a calibration that jumps is
// named (bench/fault_injection.cc measures the rest).
#include <gtest/gtest.h>

#include <algorithm>

#include "common/calibration/calibration_inputs.h"
#include "replay/replay.h"
#include "sim/simulator.h"
#include "temp_dir.h"

namespace giocal {
namespace {

CalibrationInputs simulated(const sim::SimConfig& cfg, std::uint64_t seed) {
  test::TempDir dir;
  sim::writeDataset(sim::simulate(cfg, seed), dir.file("data"));
  return loadCalibrationInputs(dir.file("data"));
}

template <class T>
void dropBetween(std::vector<T>& v, double t0, double t1) {
  v.erase(std::remove_if(v.begin(), v.end(), [&](const T& s) { return s.t >= t0 && s.t < t1; }),
          v.end());
}

bool says(const CalibrationRun& run, const std::string& text) {
  return std::any_of(run.warnings.begin(), run.warnings.end(),
                     [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

TEST(DegradedRuns, GapsOutagesAndMissingBaseAreCountedAndNamed) {
  const sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml");
  CalibrationInputs in = simulated(cfg, 33);
  const double t0 = in.rover.epochs.front().t;
  dropBetween(in.odom, t0 + 60.0, t0 + 62.0);
  dropBetween(in.odom, t0 + 90.0, t0 + 92.0);
  dropBetween(in.rover.epochs, t0 + 70.0, t0 + 100.0);
  dropBetween(in.base.epochs, t0 + 110.0, t0 + 115.0);
  for (const char* est : {"ekf", "fgo"}) {
    SCOPED_TRACE(est);
    const CalibrationRun run = replayInputs(in, {est, {}, {}}, nullptr);
    EXPECT_EQ(run.counter(Counter::kOdometerGaps), 2);
    EXPECT_EQ(run.counter(Counter::kGnssGaps), 1);
    EXPECT_GE(run.counter(Counter::kGnssWithoutBase), 4);
    EXPECT_TRUE(says(run, "odometer gap of 2.0")) << run.warnings.front();
    EXPECT_TRUE(says(run, "no GNSS epoch for 31.0 s")) << run.warnings.front();
    EXPECT_TRUE(says(run, "has no base epoch within")) << run.warnings.front();
    // An outage is not a divergence: the prediction across it is the IMU's alone.
    EXPECT_EQ(run.counter(Counter::kReinitializations), 0);
  }
  // The clean drive says none of it.
  const CalibrationRun clean = replayInputs(simulated(cfg, 33), {"ekf", {}, {}}, nullptr);
  EXPECT_EQ(clean.counter(Counter::kOdometerGaps) + clean.counter(Counter::kGnssGaps) +
                clean.counter(Counter::kGnssWithoutBase),
            0);
}

TEST(DegradedRuns, NeitherEstimatorIntegratesTheOdometerAcrossAGap) {
  // What the warning says, "the IMU navigates alone through it", holds for the factor graph too:
  // no interval factor bridges a 2 s hole by interpolating the readings at its ends.
  const sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml");
  const CalibrationInputs clean = simulated(cfg, 35);
  CalibrationInputs in = clean;
  const double t0 = in.rover.epochs.front().t;
  dropBetween(in.odom, t0 + 60.5, t0 + 62.5);
  const long with_all =
      replayInputs(clean, {"fgo", {}, {}}, nullptr).counter(Counter::kOdometerIntervals);
  const long with_gap =
      replayInputs(in, {"fgo", {}, {}}, nullptr).counter(Counter::kOdometerIntervals);
  // The 1 s intervals ending at 61, 62 and 63 s hold part of the hole.
  EXPECT_EQ(with_all - with_gap, 3);
}

TEST(DegradedRuns, TheFactorGraphLeavesOutWheelSlip) {
  // Paper preset, 0.5 s slips at 1.3x speed twice a minute. FGO NEES7 without the gate on seeds
  // 34-38 and 61: 142, 366, 81, 412, 25, 220; with it 202, 61, 81, 95, 25, 23 (docs/results.md);
  // the EKF's 11, 33, 6, 16, 9. Seed 35 here.
  sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml");
  cfg.odometer.slip_rate_per_min = 2.0;
  const CalibrationInputs in = simulated(cfg, 35);
  const CalibrationRun run = replayInputs(in, {"fgo", {}, {}}, nullptr);
  EXPECT_GT(run.counter(Counter::kOdometerRejected), 0);
  // Consistency under slip is tested over ten seeds
  // (BothEstimatorsStayConsistentUnderWheelSlip...): one seed's NEES bound passes or fails by luck.
}

// Consistency under wheel slip (0.5 s at 1.3x speed twice a minute), both estimators, over ten
// seeds never used while developing: a consistent estimator's NEES7 is under its 95 % bound
// (14.07) with probability 0.95, so at least 8 of 10 runs (probability 0.99) must be. The field
// preset, three of its laps: on the paper preset the EKF's yaw sigma is too small even without
// slip (err/sigma 1.98, docs/results.md), which this test is not about.
TEST(DegradedRuns, BothEstimatorsStayConsistentUnderWheelSlipOverTenSeeds) {
  sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/field.yaml");
  cfg.segments.resize(2 + 4 * 3);  // the start and 3 of the 10 laps
  cfg.odometer.slip_rate_per_min = 2.0;
  std::vector<CalibrationInputs> drives;
  for (std::uint64_t seed = 3101; seed <= 3110; ++seed) drives.push_back(simulated(cfg, seed));
  for (const char* est : {"ekf", "fgo"}) {
    SCOPED_TRACE(est);
    int under = 0;
    std::string nees;
    for (const CalibrationInputs& in : drives) {
      const CalibrationRun run = replayInputs(in, {est, {}, {}}, nullptr);
      const double n = calibrationError(run.final(), in.truth->calib).nees7;
      under += n < 14.07;
      nees += " " + std::to_string(n);
    }
    EXPECT_GE(under, 8) << "NEES7 of seeds 3101-3110:" << nees;
  }
}

TEST(DegradedRuns, TheFactorGraphLeavesOutSlippingOdometerSamples) {
  // Paper seed 63 with wheel slip: the samples checked against the IMU between the solved states
  // show the bursts, and leaving them out keeps the run consistent; the clean drive of the seed
  // loses no sample. (With the odometer gate testing the predicted residual, the check is
  // about neutral on the paper preset: NEES7 5.8 with it, 4.9 without on this seed, 22.6 and
  // 31.7 on seed 66; docs/results.md.)
  sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml");
  const CalibrationRun clean = replayInputs(simulated(cfg, 63), {"fgo", {}, {}}, nullptr);
  EXPECT_EQ(clean.counter(Counter::kOdometerSlips), 0);
  cfg.odometer.slip_rate_per_min = 2.0;
  const CalibrationInputs in = simulated(cfg, 63);
  FgoOptions unchecked;
  unchecked.odometer_slip_sigma = 0.0;
  const CalibrationRun before = replayInputs(in, {"fgo", {}, unchecked}, nullptr);
  const CalibrationRun run = replayInputs(in, {"fgo", {}, {}}, nullptr);
  EXPECT_EQ(before.counter(Counter::kOdometerSlips), 0);
  EXPECT_GT(run.counter(Counter::kOdometerSlips), 30);
}

TEST(DegradedRuns, ACalibrationThatJumpsIsNamed) {
  // Paper seed 63 whose odometer reads 10 % more from 80 s on (a wheel changed, a softer tyre):
  // the data after disagree with those before, and the estimate moves further in one epoch than
  // one epoch's data can move it (chi-square in its sigmas before, gate 29.9 at 7 dof). Both
  // estimators name it; the clean drive of the seed steps by less. (Until 2026-11-27 this test
  // used wheel slip with the factor graph's slip check off; since its odometer gate tests the
  // residual the rest of the window predicts, the gate takes those intervals out first.)
  const sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml");
  const CalibrationInputs clean = simulated(cfg, 63);
  CalibrationInputs in = clean;
  const double t0 = in.rover.epochs.front().t;
  for (OdomSample& s : in.odom)
    if (s.t >= t0 + 80.0) s.v *= 1.1;
  for (const char* est : {"ekf", "fgo"}) {
    SCOPED_TRACE(est);
    EXPECT_EQ(replayInputs(clean, {est, {}, {}}, nullptr).counter(Counter::kCalibrationJumps), 0);
    const CalibrationRun run = replayInputs(in, {est, {}, {}}, nullptr);
    EXPECT_GE(run.counter(Counter::kCalibrationJumps), 1);
    EXPECT_TRUE(says(run, "the calibration moved further in one epoch")) << run.warnings.front();
  }
}

TEST(DegradedRuns, BothEstimatorsSayWhenTheyDivergeAndStartAgain) {
  // From 80 s on, the rover's pseudo-ranges carry 200-1000 m that differ by satellite (what a
  // diverged navigation state looks like to the DD code rows); the carrier phase is untouched.
  // Both estimators must say so and re-initialize, instead of rejecting every row and drifting
  // (the factor graph did not test for divergence before; docs/results.md).
  const sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml");
  CalibrationInputs in = simulated(cfg, 36);
  const double t0 = in.rover.epochs.front().t;
  for (ObsEpoch& e : in.rover.epochs) {
    if (e.t < t0 + 80.0) continue;
    for (SatObs& s : e.sats) {
      for (SignalObs& o : s.signals) o.P += 200.0 * (1 + s.sat.prn % 5);
    }
  }
  for (const char* est : {"ekf", "fgo"}) {
    SCOPED_TRACE(est);
    const CalibrationRun run = replayInputs(in, {est, {}, {}}, nullptr);
    EXPECT_GE(run.counter(Counter::kReinitializations), 1);
    EXPECT_TRUE(says(run, "the estimator diverged at t=")) << run.warnings.front();
  }
}

}  // namespace
}  // namespace giocal
