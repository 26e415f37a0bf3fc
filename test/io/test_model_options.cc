#include <gtest/gtest.h>

#include "common/io/data_error.h"
#include "common/io/model_options.h"
#include "temp_dir.h"

namespace giocal {
namespace {

TEST(ModelOptions, ShippedConfigEqualsTheDefaults) {
  const ModelOptions shipped =
      readModelOptions(std::string(GIOCAL_SOURCE_DIR) + "/config/giocal.yaml");
  const ModelOptions defaults;
  EXPECT_DOUBLE_EQ(shipped.motion.window_s, defaults.motion.window_s);
  EXPECT_NEAR(shipped.motion.zupt_max_gyro, defaults.motion.zupt_max_gyro, 1e-15);
  EXPECT_NEAR(shipped.motion.nhc_max_gyro, defaults.motion.nhc_max_gyro, 1e-15);
  EXPECT_DOUBLE_EQ(shipped.motion.nhc_min_speed, defaults.motion.nhc_min_speed);
  EXPECT_DOUBLE_EQ(shipped.zupt_sigma, defaults.zupt_sigma);
  EXPECT_DOUBLE_EQ(shipped.nhc_sigma, defaults.nhc_sigma);
  EXPECT_DOUBLE_EQ(shipped.lateral_speed_density, defaults.lateral_speed_density);
  EXPECT_DOUBLE_EQ(shipped.tilt_rate_density, defaults.tilt_rate_density);
}

TEST(ModelOptions, OverridesAndBadValues) {
  test::TempDir dir;
  const auto p = dir.write("c.yaml", "models:\n  nhc_min_speed: 0.2\n");
  EXPECT_DOUBLE_EQ(readModelOptions(p).motion.nhc_min_speed, 0.2);
  EXPECT_DOUBLE_EQ(readModelOptions(p).zupt_sigma, ModelOptions().zupt_sigma);
  const auto bad = dir.write("b.yaml", "models:\n  zupt_sigma: -1\n");
  try {
    readModelOptions(bad);
    FAIL();
  } catch (const DataError& e) {
    EXPECT_EQ(e.line(), 2);
    EXPECT_NE(std::string(e.what()).find("models.zupt_sigma"), std::string::npos);
  }
}

}  // namespace
}  // namespace giocal
