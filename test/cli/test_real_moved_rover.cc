// Real GNSS on a moving antenna whose path is known: a static real rover moved along the field
// preset (simulate --static-rover), with the preset's IMU and odometer. The mosaic pair (1 m, 1 s,
// five systems) along two laps: giocal rtk, both calibrators with the base, and both with the
// rover alone; the GSI pair (Trimble 5700, 3.3 km, 30 s, GPS) along the whole drive.
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
const std::string kGsi = std::string(GIOCAL_SOURCE_DIR) + "/data/real/gsi-static-0759-3040/";
// The GSI stations: the base as RTKLIB's test makefile states it (SOURCE.txt), the rover as the
// mean of RTKLIB's fixed solution of the pair (rtklib_reference.pos).
const std::string kGsiBase = "-3978241.958,3382840.234,3649900.853";
const std::string kGsiRover = "-3976219.1875,3382371.6044,3652511.1414";

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
// prior's (an estimator that did nothing fails those), NEES7 within chi-square's 99.9 %. A run
// that cannot reach the yaw target says so in its sigma: `yaw` then gives its own target and the
// share of the prior its sigma must stay under.
struct YawBound {
  double target = 0.5;  // [deg]
  double share_of_prior = 0.1;
};
void expectCalibrated(const nlohmann::json& s, const std::string& what, YawBound yaw = {}) {
  ASSERT_EQ(s["status"], "ok") << what;
  const nlohmann::json &e = s["error"], &sd = s["sd"];
  const auto check = [&](const nlohmann::json& err, const nlohmann::json& sigma, double target,
                         double prior, double share, const char* name) {
    EXPECT_LT(std::abs(err.get<double>()), target) << what << " " << name;
    EXPECT_LT(std::abs(err.get<double>()), 4.0 * sigma.get<double>()) << what << " " << name;
    EXPECT_LT(sigma.get<double>(), share * prior) << what << " " << name;
  };
  check(e["s_v"], sd["s_v"], 2e-3, 0.02, 0.1, "s_v");
  check(e["p_b_m"][0], sd["p_b_m"][0], 0.05, 0.5, 0.1, "p_b_m.x");
  check(e["p_b_m"][1], sd["p_b_m"][1], 0.05, 0.5, 0.1, "p_b_m.y");
  check(e["rpy_b_m_deg"][2], sd["rpy_b_m_deg"][2], yaw.target, 5.0, yaw.share_of_prior, "yaw");
  EXPECT_LT(e["nees7"].get<double>(), 24.32) << what;
}

// Each epoch of a giocal rtk solution against the antenna's true position: every epoch fixed,
// the distances sorted.
std::vector<double> fixedMisses(const std::string& pos, const std::string& data) {
  const std::vector<PositionFix> fixes = readPosFile(pos);
  const TruthCalibration truth = readTruthCalibration(data + "/truth_calib.yaml");
  std::map<long, TruthSample> at_second;
  for (const TruthSample& s : readTruthCsv(data + "/truth.csv")) {
    if (std::abs(s.t - std::round(s.t)) < 1e-6) at_second[std::lround(s.t)] = s;
  }
  std::vector<double> miss;
  for (const PositionFix& f : fixes) {
    EXPECT_EQ(f.quality, 1) << f.t;
    const TruthSample& s = at_second.at(std::lround(f.t));
    const Eigen::Matrix3d R_e_l = rotationEcefFromEnu(s.lat_deg * kDegToRad, s.lon_deg * kDegToRad);
    const Eigen::Vector3d antenna =
        ecefFromGeodetic({s.lat_deg * kDegToRad, s.lon_deg * kDegToRad, s.h}) +
        R_e_l * (s.q_n_b * truth.p_b_g);
    miss.push_back((f.p_e - antenna).norm());
  }
  std::sort(miss.begin(), miss.end());
  return miss;
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
    // 261 of the file's 301 epochs; GLONASS, which giocal does not process, left out. QZSS is
    // in since its ephemerides count as healthy (32564 signals before, 2026-12-01).
    EXPECT_NE(r.out.find("261 epochs, 34913 signals moved"), std::string::npos) << r.out;
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
  const std::vector<double> miss = fixedMisses(drive.dir.file("rtk.pos"), data);
  ASSERT_EQ(miss.size(), 261u);
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
    // The extrinsic roll: -0.043 deg in both estimators while the ionosphere's slow change was
    // left in the time differences, -0.020 with it taken out (IonosphereRate; the base: -0.007).
    EXPECT_LT(std::abs(s["error"]["rpy_b_m_deg"][0].get<double>()), 0.03) << estimator;
  }
}

// A second make and a longer baseline: two Trimble 5700 stations of 2005, 3.3 km apart, GPS L1/L2
// every 30 s, the rover moved along the whole field drive (1244 s, 42 epochs). Its tags run up to
// 5 ms off the receiver's clock (SOURCE.txt), so the move takes the path at the true reception
// time. The rover alone is not calibrated: 30 s is too long for TDCP pairs (results.md).
TEST(RealMovedRover, GsiTrimbleRoverMovedAlongTheFieldDriveFixesAndCalibrates) {
  test::TempDir dir;
  const std::string data = dir.file("moved");
  const test::GiocalResult r =
      test::runGiocalOk("simulate --config " + test::fieldPresetWithLaps(dir, 10) +
                        " --seed 21 --static-rover " + kGsi + "07590920.05o --rover-pos " +
                        kGsiRover + " --base " + kGsi + "30400920.05o --base-pos " + kGsiBase +
                        " --nav " + kGsi + "30400920.05n " + kGsi + "07590920.05n --out " + data);
  EXPECT_NE(r.out.find("42 epochs"), std::string::npos) << r.out;
  test::runGiocalOk("rtk --rover " + data + "/rover.obs --base " + data + "/base.obs --nav " +
                    data + "/nav.rnx --base-pos " + kGsiBase + " --out " + dir.file("rtk.pos"));
  const std::vector<double> miss = fixedMisses(dir.file("rtk.pos"), data);
  ASSERT_EQ(miss.size(), 42u);
  // Each epoch's own noise: the static pair's RTKLIB solution scatters 3, 5 and 10 mm (E, N, U).
  EXPECT_LT(miss[static_cast<size_t>(0.95 * 41)], 0.015);  // measured 12.1 mm
  EXPECT_LT(miss.back(), 0.03);                            // measured 23.3 mm
  for (const std::string estimator : {"ekf", "fgo"}) {
    const std::string out = dir.file("cal_" + estimator);
    test::runGiocalOk("calibrate --data " + data + " --estimator " + estimator +
                      " --no-validate --quiet --out " + out);
    const nlohmann::json s = summaryOf(out);
    EXPECT_GE(s["fix_rate"].get<double>(), 0.95) << estimator;  // measured 1.0 and 1.0
    // The factor graph, one state per GNSS epoch, determines yaw less well with epochs 30 s apart
    // (sigma 0.62 deg on this seed; on simulated field drives 0.72 deg mean error at err/sigma
    // 1.17, against 0.21 deg at 1 s: bench/gnss_interval.sh), so the yaw target is the EKF's;
    // both must be consistent and well inside the prior.
    expectCalibrated(s, estimator + " with the GSI base",
                     estimator == "ekf" ? YawBound{} : YawBound{2.0, 0.2});
  }
}

}  // namespace
}  // namespace giocal
