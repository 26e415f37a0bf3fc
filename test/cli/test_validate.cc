// giocal validate: a calibration checked on the drive without a truth, by GNSS outages
// dead-reckoned with it and with the guess against the GNSS solution.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "field_laps.h"
#include "run_giocal.h"
#include "temp_dir.h"

namespace giocal {
namespace {

nlohmann::json summaryOf(const std::string& dir) {
  std::ifstream in(dir + "/summary.json");
  return nlohmann::json::parse(in);
}

// Three laps of the field preset (a seed not used while developing): the EKF's calibration
// dead-reckons every window better than the guess, against the dataset's own RTK fixes.
TEST(Validate, ACalibrationOfASimulatedDriveIsBetterThanTheGuessInEveryWindow) {
  test::TempDir dir;
  const std::string preset = test::fieldPresetWithLaps(dir, 3);
  ASSERT_EQ(
      test::runGiocal("simulate --config " + preset + " --out " + dir.file("data") + " --seed 3201")
          .code,
      0);
  ASSERT_EQ(
      test::runGiocal("calibrate --data " + dir.file("data") + " --quiet --out " + dir.file("cal"))
          .code,
      0);
  const test::GiocalResult r =
      test::runGiocal("validate --data " + dir.file("data") + " --run " + dir.file("cal") +
                      " --quiet --out " + dir.file("val"));
  ASSERT_EQ(r.code, 0) << r.out;
  const nlohmann::json s = summaryOf(dir.file("val"));
  ASSERT_EQ(s["windows"].size(), 5u) << r.out;
  for (const auto& w : s["windows"]) {
    EXPECT_LT(w["calibrated_m"].get<double>(), w["guess_m"].get<double>()) << r.out;
    EXPECT_NEAR(w["duration_s"].get<double>(), 60.0, 1.0);
  }
  EXPECT_EQ(s["verdict"], "better");
  EXPECT_LT(s["ratio"].get<double>(), 0.5);
  EXPECT_EQ(s["better_windows"], 5);
  EXPECT_NEAR(s["confidence"].get<double>(), 1.0 - 1.0 / 32.0, 1e-12);  // the sign test, 5 of 5
  const std::string last = r.out.substr(r.out.rfind("\n", r.out.size() - 2) + 1);
  EXPECT_EQ(last.find("  verdict: better"), 0u) << last;

  // Nothing is overwritten without --overwrite; a window longer than the drive says what it needs.
  const test::GiocalResult again =
      test::runGiocal("validate --data " + dir.file("data") + " --run " + dir.file("cal") +
                      " --out " + dir.file("val"));
  EXPECT_NE(again.code, 0);
  EXPECT_NE(again.out.find("give --overwrite"), std::string::npos) << again.out;
  const test::GiocalResult long_window =
      test::runGiocal("validate --data " + dir.file("data") + " --run " + dir.file("cal") +
                      " --outage 2000 --out " + dir.file("val2"));
  EXPECT_NE(long_window.code, 0);
  EXPECT_NE(long_window.out.find("validate needs at least"), std::string::npos) << long_window.out;
  const test::GiocalResult no_run =
      test::runGiocal("validate --data " + dir.file("data") + " --run " + dir.file("nothing") +
                      " --out " + dir.file("val3"));
  EXPECT_NE(no_run.code, 0);
  EXPECT_NE(no_run.out.find("calibration.csv: missing"), std::string::npos) << no_run.out;
}

}  // namespace
}  // namespace giocal
