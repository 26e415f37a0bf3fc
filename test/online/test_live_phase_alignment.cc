// The live Calibrator checks each receiver's phases of one band as they come (a file's reader
// checks the whole file; a driver's raw epochs are not checked by anyone else): a base of another
// make whose L2X phases sit a quarter cycle from its L2W is aligned and named, and calibrates as
// the same base read from its file (the stream's own rules: test_phase_alignment.cc).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/calibration/calibration_inputs.h"
#include "common/gnss/phase_alignment.h"
#include "common/gnss/rinex_obs.h"
#include "replay/estimator_factory.h"
#include "sim/base_of_another_make.h"
#include "sim/simulator.h"
#include "temp_dir.h"

namespace giocal {
namespace {

// Fed in time order, as a robot's drivers would.
CalibrationRun feed(const CalibrationInputs& in) {
  auto cal = makeCalibrator("ekf", in.description, in.base_e, CalibrationOptions{}, {}, nullptr);
  cal->addNavigation(in.nav);
  size_t kr = 0, kb = 0, ko = 0;
  for (const ImuSample& s : in.imu) {
    while (ko < in.odom.size() && in.odom[ko].t <= s.t) cal->addOdometer(in.odom[ko++]);
    while (kr < in.rover.epochs.size() && in.rover.epochs[kr].t <= s.t)
      cal->addRover(in.rover.epochs[kr++]);
    while (kb < in.base.epochs.size() && in.base.epochs[kb].t <= s.t)
      cal->addBase(in.base.epochs[kb++]);
    cal->addImu(s);
  }
  cal->finish();
  return cal->run();
}

TEST(LivePhaseAlignment, RawPhasesOfABaseOfAnotherMakeCalibrateAsItsAlignedFile) {
  const sim::SimConfig cfg = test::paperWithBaseOfAnotherMake(false);
  test::TempDir dir;
  const std::string data = dir.file("d");
  sim::writeDataset(sim::simulate(cfg, 4), data);
  // The file's reader aligns the whole file; the same epochs with that repair taken back are
  // what a driver of this receiver would push.
  const CalibrationInputs aligned = loadCalibrationInputs(data);
  const RinexObsReader reader(data + "/base.obs");
  ASSERT_EQ(reader.phaseOffsets().size(), 2u);
  CalibrationInputs raw = aligned;
  for (ObsEpoch& e : raw.base.epochs) {
    for (SatObs& s : e.sats) {
      for (SignalObs& g : s.signals) {
        for (const SignalOffset& o : reader.phaseOffsets()) {
          if (o.sys == static_cast<char>(s.sat.sys) && o.band == g.band && o.attr == g.attr)
            g.L += o.applied;
        }
      }
    }
  }
  const CalibrationRun from_file = feed(aligned), live = feed(raw);
  const auto named = [&](const std::string& text) {
    return std::any_of(live.warnings.begin(), live.warnings.end(),
                       [&](const std::string& w) { return w.find(text) != std::string::npos; });
  };
  EXPECT_TRUE(named("the base's epochs: G L2X phases sit +0.25 cycles from L2W's"));
  EXPECT_TRUE(named("the base's epochs: J L1X phases sit -0.2"));
  EXPECT_TRUE(named("aligned to L1C by +0.25 cycles"));
  std::cout << "fixed epochs: file " << from_file.fixed_epochs << " of " << from_file.gnss_epochs
            << ", raw phases fed live " << live.fixed_epochs << " of " << live.gnss_epochs << "\n";
  EXPECT_GE(from_file.fixed_epochs, from_file.gnss_epochs * 9 / 10);
  EXPECT_GE(live.fixed_epochs, from_file.fixed_epochs - 1);
  const CalibrationEstimate &a = live.final(), &b = from_file.final();
  const Eigen::Matrix<double, 8, 1> sd = b.sigma();
  // The same phases but for rounding (an aligned phase is raw + 0.25 - 0.25): within 1e-4 of the
  // sigmas (measured 1e-6). Fed raw without the check, the quarter cycles of the satellites the
  // base tracks as L2X alone move s_v by 9e-3 of its sigma (2026-12-02): their fixes and rows
  // are checked out one by one, so the fix count stays the same.
  EXPECT_NEAR(a.calib.s_v, b.calib.s_v, 1e-4 * sd[0]);
  EXPECT_NEAR(a.calib.p_b_m.x(), b.calib.p_b_m.x(), 1e-4 * sd[2]);
  EXPECT_NEAR(a.calib.p_b_m.y(), b.calib.p_b_m.y(), 1e-4 * sd[3]);
  EXPECT_NEAR(a.sigma()[7], sd[7], 1e-4 * sd[7]);
}

}  // namespace
}  // namespace giocal
