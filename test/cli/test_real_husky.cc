// The real Husky bag end to end without raw GNSS: import, the LC scheme from its NavSatFix
// positions with both estimators, and dead reckoning through its last 200 s against the fixes.
// No truth exists: the checks are what any sound calibration of this robot must show.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

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

// With its heights in (the default), the fixes' 30 m fall on flat ground pulls both estimators
// and the gate then refuses most later fixes: the factor graph kept 52 of 901 and said nothing.
// Now each run names the share it could not use and the key that leaves the height out.
TEST(RealHusky, FixesTheGateRefusesAreNamedWithWhatToChange) {
  test::TempDir dir;
  const std::string data = dir.file("husky"), pos = data + "/gnss.pos";
  std::string log;
  ASSERT_EQ(importHusky(data, &log), 0) << log;
  for (const std::string est : {"ekf", "fgo"}) {
    SCOPED_TRACE(est);
    const std::string out = dir.file(est);
    log.clear();
    const int code = run("calibrate --data " + data + " --gnss lc --pos " + pos + " --estimator " +
                             est + " --quiet --out " + out,
                         &log);
    const nlohmann::json s = summary(out);
    const long unused = s["counters"]["gnss_epochs_unused"].get<long>();
    const long used = s["gnss_epochs"].get<long>();
    EXPECT_GT(unused, (unused + used) / 5);
    // More than half unused: the run does not believe its answer, says so last, and exits 3.
    const std::string status = s["status"].get<std::string>();
    if (2 * unused > unused + used) {
      EXPECT_EQ(code, 3) << log;
      EXPECT_EQ(status.rfind("suspect: ", 0), 0u) << status;
      const std::string last = log.substr(log.rfind("\n", log.size() - 2) + 1);
      EXPECT_NE(last.find("status: suspect: "), std::string::npos) << last;
    } else {
      EXPECT_EQ(code, 0) << log;
    }
    bool named = false;
    for (const auto& w : s["warnings"]) {
      const std::string text = w.get<std::string>();
      named |= text.find(std::to_string(unused) + " of " + std::to_string(unused + used) +
                         " position fixes updated nothing") != std::string::npos &&
               text.find("calibration.lc.use_height: 0") != std::string::npos;
    }
    EXPECT_TRUE(named) << s["warnings"].dump(1);
    // Checked on the drive against its fixes (60 s outages at 5 windows): the factor graph's
    // calibration dead-reckons better than the guess (mean 7.6 m against 57.2 m, 4 of 5 windows,
    // 2026-11-27); the EKF's does not yet (66.1 m against 57.1 m): "Real logs decide" is open.
    log.clear();
    ASSERT_EQ(run("validate --data " + data + " --gnss lc --pos " + pos + " --run " + out +
                      " --quiet --out " + dir.file(est + "_validate"),
                  &log),
              0)
        << log;
    const nlohmann::json v = summary(dir.file(est + "_validate"));
    EXPECT_EQ(v["windows"].size(), 5u);
    if (est == "fgo") {
      EXPECT_EQ(v["verdict"], "better") << log;
      EXPECT_LT(v["ratio"].get<double>(), 0.5) << log;
    }
  }
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

}  // namespace
}  // namespace giocal
