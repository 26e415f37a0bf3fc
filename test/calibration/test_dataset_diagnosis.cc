// The conditions that make a dataset unusable (issue 23), each named with its file: rover and base
// from different days, ephemerides of another time, no carrier phase, no motion; none on a good
// simulated drive. And calibrate, failing to initialize on such a dataset, says which it met.
#include <gtest/gtest.h>

#include <cmath>

#include "common/calibration/dataset_diagnosis.h"
#include "common/gnss/rinex_nav.h"
#include "common/gnss/rinex_obs.h"
#include "common/gnss/rinex_obs_writer.h"
#include "replay/replay.h"
#include "sim/simulator.h"
#include "temp_dir.h"

namespace giocal {
namespace {

struct Drive {
  sim::SimulatedLogs logs;
  NavData nav;
  Drive()
      : logs(sim::simulate(
            sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml"), 9)),
        nav(readRinexNav(logs.nav_file)) {}
  std::vector<std::string> diagnose(const ObsData& rover, const ObsData& base, const NavData& n,
                                    const std::vector<OdomSample>& odom) const {
    return diagnoseDataset({rover, base, n, odom, "rover.obs", "base.obs", "nav.rnx", "odom.csv"});
  }
};

ObsData obs(const std::vector<ObsEpoch>& epochs) {
  ObsData d;
  d.epochs = epochs;
  return d;
}

bool saysOnce(const std::vector<std::string>& lines, const std::string& what) {
  int n = 0;
  for (const auto& l : lines) n += l.find(what) != std::string::npos;
  return n == 1 && lines.size() == 1;
}

TEST(DatasetDiagnosis, EachUnusableConditionIsNamed) {
  const Drive d;
  const ObsData rover = obs(d.logs.gnss.rover), base = obs(d.logs.gnss.base);
  EXPECT_TRUE(d.diagnose(rover, base, d.nav, d.logs.odom).empty());

  ObsData next_day = base;
  for (auto& e : next_day.epochs) e.t += 86400.0;
  const auto a = d.diagnose(rover, next_day, d.nav, d.logs.odom);
  EXPECT_TRUE(saysOnce(a, "rover.obs and base.obs have no epoch within 0.5 s of each other"))
      << (a.empty() ? "" : a.front());

  NavData old = d.nav;
  for (auto& e : old.ephemerides) e.toe -= 3 * 86400.0, e.toc -= 3 * 86400.0;
  const auto b = d.diagnose(rover, base, old, d.logs.odom);
  EXPECT_TRUE(saysOnce(b, "nav.rnx: no broadcast ephemeris valid for the satellites rover.obs"))
      << (b.empty() ? "" : b.front());

  ObsData code_only = rover;
  for (auto& e : code_only.epochs)
    for (auto& s : e.sats)
      for (auto& g : s.signals) g.L = NAN;
  const auto c = d.diagnose(code_only, base, d.nav, d.logs.odom);
  EXPECT_TRUE(saysOnce(c, "rover.obs: no carrier phase")) << (c.empty() ? "" : c.front());

  std::vector<OdomSample> parked = d.logs.odom;
  for (auto& s : parked) s.v = s.w = 0.0;
  const auto e = d.diagnose(rover, base, d.nav, parked);
  EXPECT_TRUE(saysOnce(e, "odom.csv: the odometer never shows motion"))
      << (e.empty() ? "" : e.front());
}

TEST(DatasetDiagnosis, CalibrateSaysWhichConditionItMet) {
  const Drive d;
  test::TempDir dir;
  sim::writeDataset(d.logs, dir.file("data"));
  // The base's file replaced by one of the next day.
  ObsData base = readRinexObs(dir.file("data/base.obs"));
  for (auto& e : base.epochs) e.t += 86400.0;
  RinexObsHeader h;
  h.approx_position = base.header.approx_position;
  h.obs_types = base.header.obs_types;
  writeRinexObs(dir.file("data/base.obs"), h, base.epochs);
  try {
    replayFolder(dir.file("data"), {"ekf", CalibrationOptions{}, {}}, nullptr);
    FAIL() << "a base of another day was calibrated with";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("could not initialize"), std::string::npos) << what;
    EXPECT_NE(what.find("have no epoch within 0.5 s of each other"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace giocal
