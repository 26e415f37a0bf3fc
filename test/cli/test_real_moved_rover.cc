// Real GNSS on a moving antenna whose path is known: the mosaic pair's static rover moved along two
// laps of the field preset (simulate --static-rover), with the preset's IMU and odometer. giocal
// rtk, both calibrators with the base, and both with the rover alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "common/geodesy/wgs84.h"
#include "common/gnss/pos_reader.h"
#include "common/io/dataset_description.h"
#include "common/io/sensor_logs.h"
#include "common/math/rotation.h"
#include "field_laps.h"
#include "run_giocal.h"
#include "temp_dir.h"

namespace giocal {
namespace {

const std::string kMosaic = std::string(GIOCAL_SOURCE_DIR) + "/data/real/mosaic-static-nagoya/";

// "lat lon h" of the survey files, as ECEF "x,y,z" for the command line.
std::string ecefOf(const std::string& file) {
  std::ifstream in(kMosaic + file);
  double lat = 0, lon = 0, h = 0;
  in >> lat >> lon >> h;
  const Eigen::Vector3d p = ecefFromGeodetic({lat * kDegToRad, lon * kDegToRad, h});
  char text[128];
  std::snprintf(text, sizeof(text), "%.4f,%.4f,%.4f", p.x(), p.y(), p.z());
  return text;
}

nlohmann::json summaryOf(const std::string& dir) {
  std::ifstream in(dir + "/summary.json");
  return nlohmann::json::parse(in);
}

// The targets of the issues for real GNSS with synthesized motion (X, Y 5 cm, yaw 0.5 deg, s_v
// 2e-3), each error within four of the run's own sigmas and each sigma a small part of the
// prior's (an estimator that did nothing fails those), NEES7 within chi-square's 99.9 %.
void expectCalibrated(const nlohmann::json& s, const std::string& what) {
  ASSERT_EQ(s["status"], "ok") << what;
  const nlohmann::json &e = s["error"], &sd = s["sd"];
  const auto check = [&](const nlohmann::json& err, const nlohmann::json& sigma, double target,
                         double prior, const char* name) {
    EXPECT_LT(std::abs(err.get<double>()), target) << what << " " << name;
    EXPECT_LT(std::abs(err.get<double>()), 4.0 * sigma.get<double>()) << what << " " << name;
    EXPECT_LT(sigma.get<double>(), 0.1 * prior) << what << " " << name;
  };
  check(e["s_v"], sd["s_v"], 2e-3, 0.02, "s_v");
  check(e["p_b_m"][0], sd["p_b_m"][0], 0.05, 0.5, "p_b_m.x");
  check(e["p_b_m"][1], sd["p_b_m"][1], 0.05, 0.5, "p_b_m.y");
  check(e["rpy_b_m_deg"][2], sd["rpy_b_m_deg"][2], 0.5, 5.0, "yaw");
  EXPECT_LT(e["nees7"].get<double>(), 24.32) << what;
}

struct MovedDrive {
  test::TempDir dir;
  std::string preset = test::fieldPresetWithLaps(dir, 2);
  std::string simulate(const std::string& name, bool with_base) {
    const std::string base =
        with_base ? " --base " + kMosaic + "base.obs --base-pos " + ecefOf("base_position.txt")
                  : "";
    const test::GiocalResult r =
        test::runGiocalOk("simulate --config " + preset + " --seed 21 --static-rover " + kMosaic +
                          "rover.obs --rover-pos " + ecefOf("rover_position.txt") + base +
                          " --nav " + kMosaic + "base.nav --out " + dir.file(name));
    // 261 of the file's 301 epochs; GLONASS, which giocal does not process, left out.
    EXPECT_NE(r.out.find("261 epochs, 32564 signals moved"), std::string::npos) << r.out;
    return dir.file(name);
  }
};

TEST(RealMovedRover, MosaicRoverMovedAlongTwoFieldLapsFixesAndCalibrates) {
  MovedDrive drive;
  const std::string data = drive.simulate("moved", true);
  test::runGiocalOk("rtk --rover " + data + "/rover.obs --base " + data + "/base.obs --nav " +
                    data + "/nav.rnx --base-pos " + ecefOf("base_position.txt") + " --out " +
                    drive.dir.file("rtk.pos"));
  // Every epoch fixed, at the true antenna to the millimetres the static pair shows.
  const std::vector<PositionFix> fixes = readPosFile(drive.dir.file("rtk.pos"));
  const TruthCalibration truth = readTruthCalibration(data + "/truth_calib.yaml");
  std::map<long, TruthSample> at_second;
  for (const TruthSample& s : readTruthCsv(data + "/truth.csv")) {
    if (std::abs(s.t - std::round(s.t)) < 1e-6) at_second[std::lround(s.t)] = s;
  }
  std::vector<double> miss;
  for (const PositionFix& f : fixes) {
    ASSERT_EQ(f.quality, 1);
    const TruthSample& s = at_second.at(std::lround(f.t));
    const Eigen::Matrix3d R_e_l = rotationEcefFromEnu(s.lat_deg * kDegToRad, s.lon_deg * kDegToRad);
    const Eigen::Vector3d antenna =
        ecefFromGeodetic({s.lat_deg * kDegToRad, s.lon_deg * kDegToRad, s.h}) +
        R_e_l * (s.q_n_b * truth.p_b_g);
    miss.push_back((f.p_e - antenna).norm());
  }
  ASSERT_EQ(miss.size(), 261u);
  std::sort(miss.begin(), miss.end());
  EXPECT_LT(miss[static_cast<size_t>(0.95 * 260)], 0.005);  // measured 3.1 mm
  EXPECT_LT(miss.back(), 0.006);                            // measured 4.1 mm
  // The calibrators hold fixes in (nearly) every epoch giocal rtk fixes (the issue asks 95 %).
  for (const std::string estimator : {"ekf", "fgo"}) {
    const std::string out = drive.dir.file("cal_" + estimator);
    test::runGiocalOk("calibrate --data " + data + " --estimator " + estimator +
                      " --no-validate --quiet --out " + out);
    const nlohmann::json s = summaryOf(out);
    EXPECT_GE(s["fix_rate"].get<double>(), 0.995) << estimator;  // measured 1.0
    expectCalibrated(s, estimator + " with the base");
  }
}

TEST(RealMovedRover, TheSameRoverAloneCalibratesFromItsTimeDifferencedPhase) {
  MovedDrive drive;
  const std::string data = drive.simulate("alone", false);
  for (const std::string estimator : {"ekf", "fgo"}) {
    const std::string out = drive.dir.file("single_" + estimator);
    const test::GiocalResult r = test::runGiocalOk("calibrate --data " + data + " --estimator " +
                                                   estimator + " --no-validate --out " + out);
    EXPECT_NE(r.out.find("the single-receiver scheme"), std::string::npos) << r.out;
    const nlohmann::json s = summaryOf(out);
    // A static receiver's phases: no slip to flag, none screened (measured 0 and 0).
    EXPECT_GT(s["counters"]["tdcp_rows"].get<long>(), 6000) << estimator;
    EXPECT_EQ(s["counters"]["tdcp_slips"].get<long>(), 0) << estimator;
    EXPECT_EQ(s["counters"]["tdcp_screened"].get<long>(), 0) << estimator;
    expectCalibrated(s, estimator + " alone");
  }
}

}  // namespace
}  // namespace giocal
