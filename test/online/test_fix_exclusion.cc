// A fix with one wrong phase row is kept without that satellite, in both calibrators: a rover
// whose L1 phase of one satellite is a quarter cycle off (a signal tracked with another code and
// not aligned, as between receivers of two makes) fixes as the clean rover does.
#include <gtest/gtest.h>

#include <iostream>

#include "common/gnss/broadcast_orbits.h"
#include "common/gnss/dd_epoch.h"
#include "replay/replay.h"
#include "sim/simulator.h"
#include "temp_dir.h"

namespace giocal {
namespace {

// The GPS satellite of lowest elevation above 30 degrees at the first epoch: tracked through the
// drive, and not the highest, which is every group's reference.
SatId midElevationGps(const CalibrationInputs& in, const Eigen::Vector3d& antenna_e) {
  const BroadcastOrbits orbits(in.nav);
  DdEpochBuilder builder(orbits, in.base_e, DdOptions{});
  const DdEpoch ep = builder.build(in.rover.epochs.front(), in.base.epochs.front(), antenna_e);
  SatId victim;
  double lowest = 10.0;
  for (const DdObservation& o : ep.obs) {
    const double el = ep.geometry[static_cast<size_t>(o.sat_index)].el;
    if (o.sat.sys == GnssSystem::kGps && o.phase && el > 0.52 && el < lowest) {
      lowest = el;
      victim = o.sat;
    }
  }
  EXPECT_LT(lowest, 10.0);
  return victim;
}

TEST(FixExclusion, OneSatelliteAQuarterCycleOffFixesAsTheCleanRover) {
  const sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml");
  const sim::SimulatedLogs logs = sim::simulate(cfg, 4401);
  test::TempDir dir;
  sim::writeDataset(logs, dir.file("data"));
  const CalibrationInputs a = loadCalibrationInputs(dir.file("data"));
  CalibrationInputs b = a;
  const SatId victim = midElevationGps(a, logs.antenna_e.front());
  for (ObsEpoch& e : b.rover.epochs) {
    for (SatObs& s : e.sats) {
      if (s.sat != victim) continue;
      for (SignalObs& g : s.signals) {
        if (g.band == '1') g.L += 0.25;
      }
    }
  }
  for (const char* estimator : {"ekf", "fgo"}) {
    SCOPED_TRACE(estimator);
    const CalibrationRun ra = replayInputs(a, {estimator, {}, {}}, nullptr);
    const CalibrationRun rb = replayInputs(b, {estimator, {}, {}}, nullptr);
    std::cout << estimator << ": clean fixes " << ra.fixRate() << ", " << victim.str()
              << " L1 +0.25 cycle " << rb.fixRate() << " (" << rb.counters.at("fix_exclusions")
              << " fixes retried without a satellite)\n";
    EXPECT_GT(ra.fixRate(), 0.8);
    EXPECT_GT(rb.fixRate(), 0.95 * ra.fixRate());
    EXPECT_GT(rb.counters.at("fix_exclusions"), 0);
    // The calibration agrees with the clean run's within a fraction of its sigma.
    const Eigen::Matrix<double, 8, 1> sd = ra.final().sigma();
    EXPECT_LT(std::abs(rb.final().calib.s_v - ra.final().calib.s_v), 0.5 * sd[0]);
  }
}

}  // namespace
}  // namespace giocal
