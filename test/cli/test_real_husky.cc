// The real Husky bag end to end without raw GNSS: import, the LC scheme from its NavSatFix
// positions with both estimators, and dead reckoning through its last 200 s against the fixes.
// No truth exists: the checks are what any sound calibration of this robot must show.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "common/math/rotation.h"
#include "run_giocal.h"
#include "temp_dir.h"

namespace giocal {
namespace {

int run(const std::string& args, std::string* out) {
  const test::GiocalResult r = test::runGiocal(args);
  *out += r.out;
  return r.code;
}

int importHusky(const std::string& out, std::string* log) {
  return run("import --bag " + std::string(GIOCAL_SOURCE_DIR) +
                 "/data/real/husky-robot-localization/test1.bag --out " + out,
             log);
}

nlohmann::json summary(const std::string& dir) {
  std::ifstream in(dir + "/summary.json");
  return nlohmann::json::parse(in);
}

TEST(RealHusky, LooselyCoupledCalibrationAndDeadReckoningFromItsGnssFixes) {
  test::TempDir dir;
  const std::string data = dir.file("husky"), pos = data + "/gnss.pos";
  std::string log;
  ASSERT_EQ(importHusky(data, &log), 0) << log;
  // Raw GNSS is what calibrate reads by default; the message says what to do instead.
  log.clear();
  EXPECT_NE(run("calibrate --data " + data + " --out " + dir.file("tc"), &log), 0);
  EXPECT_NE(log.find("--gnss lc --pos"), std::string::npos) << log;
  // A consumer receiver's height wanders by tens of metres on this flat drive: left out.
  const std::string config = dir.file("lc.yaml");
  std::ofstream(config) << "calibration:\n  lc:\n    use_height: 0\n";
  double s_v[2] = {0, 0};
  int k = 0;
  for (const std::string est : {"ekf", "fgo"}) {
    SCOPED_TRACE(est);
    const std::string out = dir.file(est);
    log.clear();
    ASSERT_EQ(run("calibrate --data " + data + " --gnss lc --pos " + pos + " --estimator " + est +
                      " --config " + config + " --quiet --out " + out,
                  &log),
              0)
        << log;
    const nlohmann::json s = summary(out);
    // 989 fixes, the first 35 s before the heading is found.
    EXPECT_GT(s["gnss_epochs"].get<int>(), 800) << log;
    EXPECT_EQ(log.find("updated nothing"), std::string::npos) << log;
    s_v[k++] = s["final"]["s_v"].get<double>();
    EXPECT_LT(std::abs(s["final"]["s_v"].get<double>()), 0.1);
    // The IMU is mounted about 90 degrees off (gravity along its y).
    EXPECT_NEAR(s["final"]["rpy_b_m_deg"][0].get<double>(), -90.0, 3.0);
    EXPECT_LT(s["sd"]["s_v"].get<double>(), 0.01);
    log.clear();
    ASSERT_EQ(run("deadreckon --data " + data + " --gnss lc --pos " + pos + " --reference " + pos +
                      " --calibration " + out + "/summary.json --start 195 --duration 200" +
                      " --config " + config + " --quiet --out " + dir.file(est + "_dr"),
                  &log),
              0)
        << log;
    const nlohmann::json dr = summary(dir.file(est + "_dr"));
    EXPECT_GT(dr["distance_m"].get<double>(), 150.0);
    EXPECT_LT(dr["horizontal_max_m"].get<double>(), 50.0) << log;
  }
  // The two estimators see the same drive.
  EXPECT_NEAR(s_v[0], s_v[1], 0.03);
  // compare takes the LC scheme as calibrate does, and its runs are calibrate's.
  log.clear();
  ASSERT_EQ(run("compare --data " + data + " --gnss lc --pos " + pos + " --config " + config +
                    " --quiet --out " + dir.file("cmp"),
                &log),
            0)
      << log;
  EXPECT_NEAR(summary(dir.file("cmp") + "/ekf")["final"]["s_v"].get<double>(), s_v[0], 1e-9);
  EXPECT_NEAR(summary(dir.file("cmp") + "/fgo")["final"]["s_v"].get<double>(), s_v[1], 1e-9);
}

// With its heights believed, the fixes' 30 m fall on flat ground pulled both estimators and the
// gate then refused most later fixes (the factor graph kept 126 of 901, its up axis 12 deg off
// gravity). With defaults the run now checks the heights against the IMU's grade and the
// odometer's distance first (7.2 m robust spread against a stated 1.6 m), weighs them by that,
// and both estimators keep the vehicle's up axis and nearly all fixes.
TEST(RealHusky, DefaultsWeighTheWanderingHeightsByWhatTheDriveShows) {
  test::TempDir dir;
  const std::string data = dir.file("husky"), pos = data + "/gnss.pos";
  std::string log;
  ASSERT_EQ(importHusky(data, &log), 0) << log;
  // The vehicle's up axis in b as the guess has it: gravity over the drive (giocal import).
  const Eigen::Vector3d up_guess =
      rotationFromRpy(Eigen::Vector3d(-89.5377, -2.0803, 1.2396) * kDegToRad) *
      Eigen::Vector3d::UnitZ();
  double s_v[2] = {0, 0}, sd_supported[2] = {0, 0};
  int k = 0;
  for (const std::string est : {"ekf", "fgo"}) {
    SCOPED_TRACE(est);
    const std::string out = dir.file(est);
    log.clear();
    ASSERT_EQ(run("calibrate --data " + data + " --gnss lc --pos " + pos + " --estimator " + est +
                      " --quiet --out " + out,
                  &log),
              0)
        << log;
    const nlohmann::json s = summary(out);
    EXPECT_EQ(s["status"], "ok");
    const nlohmann::json& h = s["lc_heights"];
    ASSERT_TRUE(h["decided"].get<bool>()) << h.dump();
    EXPECT_NEAR(h["spread_m"].get<double>(), 7.2, 0.3);
    EXPECT_NEAR(h["reported_sigma_m"].get<double>(), 1.6, 1e-9);
    EXPECT_NEAR(h["applied_scale"].get<double>(), 4.5, 0.2);
    EXPECT_NE(log.find("their height sigmas x4.5"), std::string::npos) << log;
    // Fewer than 20 % of the fixes unused (was 22 % EKF, 86 % factor graph).
    const long unused = s["counters"]["gnss_epochs_unused"].get<long>();
    const long used = s["gnss_epochs"].get<long>();
    EXPECT_LT(unused, (unused + used) / 5) << unused << " of " << unused + used;
    // The up axis within 5 deg of gravity's (was 12.9 deg for the factor graph).
    const auto& rpy = s["final"]["rpy_b_m_deg"];
    const Eigen::Vector3d up =
        rotationFromRpy(
            Eigen::Vector3d(rpy[0].get<double>(), rpy[1].get<double>(), rpy[2].get<double>()) *
            kDegToRad) *
        Eigen::Vector3d::UnitZ();
    EXPECT_LT(std::acos(std::min(1.0, up.dot(up_guess))) * kRadToDeg, 5.0);
    // The IMU lies on its side: the lever arm along its y (the vehicle's vertical) is the one held
    // at the guess, and the other two stay on the robot (a Husky is 1 m by 0.7 m). Holding b's z,
    // the vehicle's forward axis here, let p_b_m.y wander to 0.4 m (EKF) and 1.1 m.
    const auto& p_b_m = s["final"]["p_b_m"];
    EXPECT_EQ(p_b_m[1].get<double>(), 0.0);
    EXPECT_LT(std::hypot(p_b_m[0].get<double>(), p_b_m[2].get<double>()), 0.5);
    EXPECT_NE(s["p_b_m_z"].get<std::string>().find("p_b_m.y"), std::string::npos);
    // The fixes wander: 1.3-1.4 times their sigma, alike for 14 s (69-73 fixes count as one), so
    // the run says its sigmas are about 11 times too small (measured 10.8 and 11.7).
    const nlohmann::json& lr = s["lc_residuals"];
    EXPECT_GT(lr["fixes"].get<long>(), 850);
    EXPECT_NEAR(lr["sigma_ratio"].get<double>(), 1.35, 0.2);
    EXPECT_NEAR(lr["correlation_s"].get<double>(), 14.0, 3.0);
    const double understated = lr["sigmas_understated_by"].get<double>();
    EXPECT_GT(understated, 8.0);
    EXPECT_NE(log.find("times too small"), std::string::npos) << log;
    s_v[k] = s["final"]["s_v"].get<double>();
    // The summary states the sigmas the fixes support: its own times that factor.
    ASSERT_TRUE(s.contains("sd_supported")) << s.dump();
    EXPECT_NEAR(s["sd_supported"]["s_v"].get<double>(), s["sd"]["s_v"].get<double>() * understated,
                1e-12);
    EXPECT_NEAR(s["sd_supported"]["rpy_b_m_deg"][0].get<double>(),
                s["sd"]["rpy_b_m_deg"][0].get<double>() * understated, 1e-9);
    EXPECT_NE(log.find("sd_supported"), std::string::npos) << log;
    sd_supported[k++] = s["sd_supported"]["s_v"].get<double>();
    // Checked on the drive against its fixes (60 s outages at 5 windows), 2026-11-28: EKF 7.7 m
    // against the guess's 8.1 m, factor graph 7.7 m against 8.0 m, both "no better" (ratio 0.95
    // and 0.97; 1.27 and 1.01 with b's z held). Validating better than the guess is open work
    // ("Real logs decide"); no worse than this is asserted.
    log.clear();
    ASSERT_EQ(run("validate --data " + data + " --gnss lc --pos " + pos + " --run " + out +
                      " --quiet --out " + dir.file(est + "_validate"),
                  &log),
              0)
        << log;
    const nlohmann::json v = summary(dir.file(est + "_validate"));
    EXPECT_EQ(v["windows"].size(), 5u);
    EXPECT_NE(v["verdict"], "worse") << log;
    EXPECT_LT(v["ratio"].get<double>(), 1.0) << log;
    EXPECT_LT(v["guess"].get<double>(), 10.0) << log;  // the aided stretches no longer tilt
  }
  // The estimators' s_v (-0.024 and -0.035) are 5.8 of their stated sigmas apart (0.0013 and
  // 0.0012), but within 3 of the sigmas the fixes support.
  EXPECT_LT(std::abs(s_v[0] - s_v[1]), 3.0 * std::hypot(sd_supported[0], sd_supported[1]));
}

// Left out by hand, the heights are not checked: the user's choice is the run's.
TEST(RealHusky, HeightsLeftOutByHandAreNotChecked) {
  test::TempDir dir;
  const std::string data = dir.file("husky"), pos = data + "/gnss.pos";
  std::string log;
  ASSERT_EQ(importHusky(data, &log), 0) << log;
  const std::string config = dir.file("lc.yaml");
  std::ofstream(config) << "calibration:\n  lc:\n    use_height: 0\n";
  ASSERT_EQ(run("calibrate --data " + data + " --gnss lc --pos " + pos + " --config " + config +
                    " --quiet --out " + dir.file("ekf"),
                &log),
            0)
      << log;
  EXPECT_FALSE(summary(dir.file("ekf")).contains("lc_heights"));
  EXPECT_EQ(log.find("height sigmas"), std::string::npos) << log;
}

// The odometer's delay as a calibration state on a real log it does not fit: the Husky's wheel
// odometry is about 0.39 s late (the yaw rates show it), far beyond the state's first-order
// model; the state comes out small and sure of itself. Each estimator says the two disagree and
// names the time offset the yaw rates give, rather than leaving a confident wrong delay.
TEST(RealHusky, AnOdometerDelayStateThatDisagreesWithTheYawRatesIsNamed) {
  test::TempDir dir;
  const std::string data = dir.file("husky"), pos = data + "/gnss.pos";
  std::string log;
  ASSERT_EQ(importHusky(data, &log), 0) << log;
  const std::string config = dir.file("lc.yaml");
  std::ofstream(config) << "calibration:\n  estimate_odometer_delay: 1\n  lc:\n    use_height: 0\n";
  for (const std::string est : {"ekf", "fgo"}) {
    SCOPED_TRACE(est);
    log.clear();
    ASSERT_EQ(run("calibrate --data " + data + " --gnss lc --pos " + pos + " --estimator " + est +
                      " --config " + config + " --quiet --out " + dir.file(est),
                  &log),
              0)
        << log;
    const nlohmann::json s = summary(dir.file(est));
    ASSERT_TRUE(s["final"].contains("t_d_odo")) << log;
    EXPECT_LT(std::abs(s["final"]["t_d_odo"].get<double>()), 0.1);
    EXPECT_NEAR(s["odometer_delay"]["delay_s"].get<double>(), 0.39, 0.03);
    bool named = false;
    for (const auto& w : s["warnings"]) {
      const std::string text = w.get<std::string>();
      named =
          named || (text.find("disagrees with the one the yaw rates show") != std::string::npos &&
                    text.find("time_offsets: {odometer: -0.39") != std::string::npos);
    }
    EXPECT_TRUE(named) << log;
  }
}

// The targets of "Real logs decide" (item 3) and "What a reviewer found" (item 5) on this bag, as
// the issues state them: each estimator's calibration validates better than the guess, and the
// two agree within three combined stated sigmas on every parameter. Neither holds today
// (2026-11-28: "no better" at ratios 0.95 and 0.97; s_v 5.9 and roll 4.9 combined sigmas apart;
// docs/results.md, "What limits validate on the Husky bag"), so ctest runs this test with
// WILL_FAIL (label real_open, test/labels.cmake): it reports the day the targets are met instead
// of being loosened. That its pipeline runs is asserted by the tests above.
TEST(RealHusky, OpenTargetBothValidateBetterAndAgreeWithinThreeSigmas) {
  test::TempDir dir;
  const std::string data = dir.file("husky"), pos = data + "/gnss.pos";
  std::string log;
  ASSERT_EQ(importHusky(data, &log), 0) << log;
  nlohmann::json s[2];
  for (int k = 0; k < 2; ++k) {
    const std::string est = k == 0 ? "ekf" : "fgo", out = dir.file(est);
    ASSERT_EQ(run("calibrate --data " + data + " --gnss lc --pos " + pos + " --estimator " + est +
                      " --quiet --out " + out,
                  &log),
              0)
        << log;
    s[k] = summary(out);
    EXPECT_EQ(s[k]["validation"]["verdict"].get<std::string>(), "better") << est;
  }
  // Each parameter with its stated sigma (p_b_m.y, held at the guess, agrees by construction).
  const auto agree = [&](const std::string& name, const std::string& key, int i) {
    const auto at = [&](const nlohmann::json& j) {
      return i < 0 ? j[key].get<double>() : j[key][static_cast<size_t>(i)].get<double>();
    };
    const double d = std::abs(at(s[0]["final"]) - at(s[1]["final"]));
    EXPECT_LE(d, 3.0 * std::hypot(at(s[0]["sd"]), at(s[1]["sd"]))) << name;
  };
  agree("s_v", "s_v", -1);
  agree("s_w", "s_w", -1);
  for (int i = 0; i < 3; ++i) {
    agree("p_b_m " + std::to_string(i), "p_b_m", i);
    agree("rpy_b_m " + std::to_string(i), "rpy_b_m_deg", i);
  }
}

}  // namespace
}  // namespace giocal
