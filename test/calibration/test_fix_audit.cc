#include <gtest/gtest.h>

#include "common/calibration/fix_audit.h"
#include "common/geodesy/wgs84.h"
#include "common/io/sensor_logs.h"
#include "common/math/rotation.h"
#include "temp_dir.h"

namespace giocal {
namespace {

// A truth drive due north at 1 m/s, IMU level and heading north, antenna 0.5 m above it; epochs
// whose estimated antenna is 1 cm or 10 cm off horizontally (and 8 cm off vertically: not counted).
TEST(FixAudit, CountsFixedEpochsWhoseAntennaIsFarFromTheTruthHorizontally) {
  test::TempDir dir;
  std::vector<TruthSample> truth;
  const double lat0 = 35.0, lon0 = 137.0;
  for (int k = 0; k <= 100; ++k) {
    TruthSample s;
    s.t = 1000.0 + 0.1 * k;
    s.lat_deg = lat0 + (0.1 * k) / 6378137.0 * kRadToDeg;
    s.lon_deg = lon0;
    s.h = 50.0;
    s.v_enu = {0.0, 1.0, 0.0};
    truth.push_back(s);
  }
  const std::string path = dir.path() + "/truth.csv";
  writeTruthCsv(path, truth);
  const Eigen::Vector3d p_b_g(0.0, 0.0, 0.5);
  const auto antennaAt = [&](double t, const Eigen::Vector3d& off_enu) {
    const double lat = (lat0 + (t - 1000.0) / 6378137.0 * kRadToDeg) * kDegToRad;
    const double lon = lon0 * kDegToRad;
    return Eigen::Vector3d(ecefFromGeodetic({lat, lon, 50.5}) +
                           rotationEcefFromEnu(lat, lon) * off_enu);
  };
  RunRecording next;
  FixAudit audit(path, p_b_g, &next);
  GnssEpochRecord g;
  g.fixed = true;
  g.t = 1001.05;  // between truth rows: interpolated
  g.antenna_e = antennaAt(g.t, {0.01, 0.0, 0.08});
  audit.gnssEpoch(g);
  g.t = 1002.0;
  g.antenna_e = antennaAt(g.t, {0.0, -0.10, 0.0});
  audit.gnssEpoch(g);
  g.t = 1003.0;
  g.fixed = false;  // float: not a fix to check
  g.antenna_e = antennaAt(g.t, {1.0, 0.0, 0.0});
  audit.gnssEpoch(g);
  g.t = 1020.0;  // after the truth ends
  g.fixed = true;
  audit.gnssEpoch(g);
  CalibrationRun run;
  audit.addTo(run);
  EXPECT_EQ(run.counters.at("fixes_checked_against_truth"), 2);
  EXPECT_EQ(run.counters.at("wrong_fixes"), 1);
  ASSERT_EQ(run.warnings.size(), 1u);
  EXPECT_NE(run.warnings[0].find("1 of 2 fixed epochs"), std::string::npos) << run.warnings[0];
  EXPECT_NE(run.warnings[0].find("worst 0.10 m at t=1002.0"), std::string::npos)
      << run.warnings[0];
}

}  // namespace
}  // namespace giocal
