#include <gtest/gtest.h>

#include "common/calibration/fix_audit.h"
#include "common/geodesy/wgs84.h"
#include "common/io/data_error.h"
#include "common/io/scenes_csv.h"
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
  // Two scenes: the first two epochs in open sky, the third under trees, the last in none.
  FixAudit audit(path, p_b_g, &next, 0.05,
                 {{1000.0, 1001.5, "open_sky"}, {1001.5, 1010.0, "more_trees"}});
  GnssEpochRecord g;
  g.used = true;
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
  EXPECT_EQ(run.counters.at("scene.open_sky.gnss_epochs"), 1);
  EXPECT_EQ(run.counters.at("scene.open_sky.fixed_epochs"), 1);
  EXPECT_EQ(run.counters.at("scene.open_sky.wrong_fixes"), 0);
  EXPECT_EQ(run.counters.at("scene.more_trees.gnss_epochs"), 2);
  EXPECT_EQ(run.counters.at("scene.more_trees.fixed_epochs"), 1);
  EXPECT_EQ(run.counters.at("scene.more_trees.wrong_fixes"), 1);
  ASSERT_EQ(run.warnings.size(), 1u);
  EXPECT_NE(run.warnings[0].find("1 of 2 fixed epochs"), std::string::npos) << run.warnings[0];
  EXPECT_NE(run.warnings[0].find("worst 0.10 m at t=1002.0"), std::string::npos) << run.warnings[0];
}

TEST(ScenesCsv, RoundTripAndBadRowsNamed) {
  test::TempDir dir;
  const std::string path = dir.file("scenes.csv");
  writeScenesCsv(path, {{1e9, 1e9 + 320.5, "open_sky"}, {1e9 + 320.5, 1e9 + 600, "building"}});
  const std::vector<SceneSpan> back = readScenesCsv(path);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_DOUBLE_EQ(back[0].t_end, 1e9 + 320.5);
  EXPECT_EQ(sceneAt(back, 1e9 + 400), "building");
  EXPECT_EQ(sceneAt(back, 1e9 + 600), "");
  dir.write("bad.csv", "t_start,t_end,type\n5,4,open_sky\n");
  try {
    readScenesCsv(dir.file("bad.csv"));
    FAIL() << "no error";
  } catch (const DataError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.csv:2"), std::string::npos) << e.what();
  }
  dir.write("bad2.csv", "t_start,t_end,type\n5x,6,open_sky\n");
  EXPECT_THROW(readScenesCsv(dir.file("bad2.csv")), DataError);
}

}  // namespace
}  // namespace giocal
