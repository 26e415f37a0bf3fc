#include <gtest/gtest.h>

#include "common/io/data_error.h"
#include "options/giocal_config.h"
#include "temp_dir.h"

namespace giocal {
namespace {

std::string errorOf(const std::string& path) {
  try {
    readGiocalConfig(path);
  } catch (const DataError& e) {
    return e.what();
  }
  return "";
}

TEST(GiocalConfig, TheShippedConfigHasOnlyKnownKeysAndItsDefaults) {
  const GiocalConfig c = readGiocalConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/giocal.yaml");
  const GiocalConfig d = readGiocalConfig("");
  EXPECT_EQ(c.calibration.odometer_iterations, d.calibration.odometer_iterations);
  EXPECT_EQ(c.fgo.window, d.fgo.window);
  EXPECT_EQ(c.calibration.online.reorder_lag_s, d.calibration.online.reorder_lag_s);
  EXPECT_EQ(c.calibration.online.convergence.sigma_yaw_deg,
            d.calibration.online.convergence.sigma_yaw_deg);
}

TEST(GiocalConfig, AMisspelledKeyNamesTheFileLineKeyAndTheNearestValidOne) {
  test::TempDir dir;
  const std::string p =
      dir.write("c.yaml", "fgo:\n  window: 10\ncalibration:\n  odometer_iterationz: 3\n");
  EXPECT_EQ(errorOf(p), p + ":4: unknown key 'calibration.odometer_iterationz'; did you mean "
                            "'calibration.odometer_iterations'?");
  const std::string q = dir.write("d.yaml", "online:\n  convergence:\n    steady: 3\n");
  EXPECT_NE(errorOf(q).find(":3: unknown key 'online.convergence.steady'"), std::string::npos)
      << errorOf(q);
  const std::string r = dir.write("e.yaml", "nonsense_section: 1\n");
  EXPECT_EQ(errorOf(r), r + ":1: unknown key 'nonsense_section' (not a giocal option)");
}

// The record of the options in effect (summary.json "options"): the file's values and every
// default, each under its dotted key, the same set with or without a file.
TEST(GiocalConfig, RecordsEveryOptionInEffectDefaultsIncluded) {
  test::TempDir dir;
  const GiocalConfig c = readGiocalConfig(dir.write("c.yaml", "fgo:\n  window: 12\n"));
  const GiocalConfig d = readGiocalConfig("");
  EXPECT_EQ(c.in_effect.at("fgo.window"), "12");
  EXPECT_EQ(d.in_effect.at("fgo.window"), std::to_string(d.fgo.window));
  EXPECT_EQ(c.in_effect.at("calibration.odometer_iterations"),
            std::to_string(d.calibration.odometer_iterations));
  EXPECT_GT(d.in_effect.size(), 40u);
  EXPECT_EQ(c.in_effect.size(), d.in_effect.size());
}

}  // namespace
}  // namespace giocal
