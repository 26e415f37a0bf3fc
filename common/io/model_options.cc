#include "common/io/model_options.h"

#include "common/io/yaml_fields.h"
#include "common/math/rotation.h"

namespace giocal {

ModelOptions readModelOptions(const std::string& path) {
  if (path.empty()) return {};
  return readModelOptions(YamlFields(path));
}

ModelOptions readModelOptions(const YamlFields& y) {
  ModelOptions o;
  const std::string s = "models.";
  o.motion.window_s = y.numberOr(s + "motion_window_s", o.motion.window_s, 0.05, 60.0);
  o.motion.zupt_max_gyro =
      y.numberOr(s + "zupt_max_gyro_deg_s", o.motion.zupt_max_gyro * kRadToDeg, 0.0, 100.0) *
      kDegToRad;
  o.motion.zupt_max_accel_change =
      y.numberOr(s + "zupt_max_accel_change", o.motion.zupt_max_accel_change, 0.0, 100.0);
  o.motion.zupt_max_speed = y.numberOr(s + "zupt_max_speed", o.motion.zupt_max_speed, 0.0, 10.0);
  o.motion.nhc_max_gyro =
      y.numberOr(s + "nhc_max_gyro_deg_s", o.motion.nhc_max_gyro * kRadToDeg, 0.0, 1000.0) *
      kDegToRad;
  o.motion.nhc_min_speed = y.numberOr(s + "nhc_min_speed", o.motion.nhc_min_speed, 0.0, 100.0);
  o.zupt_sigma = y.numberOr(s + "zupt_sigma", o.zupt_sigma, 1e-6, 10.0);
  o.nhc_sigma = y.numberOr(s + "nhc_sigma", o.nhc_sigma, 1e-6, 10.0);
  o.nhc_interval_s = y.numberOr(s + "nhc_interval_s", o.nhc_interval_s, 0.0, 10.0);
  o.lateral_speed_density =
      y.numberOr(s + "lateral_speed_density", o.lateral_speed_density, 0.0, 10.0);
  o.tilt_rate_density = y.numberOr(s + "tilt_rate_density", o.tilt_rate_density, 0.0, 10.0);
  o.lever_arm_min_turn = y.numberOr(s + "lever_arm_min_turn", o.lever_arm_min_turn, 0.0, 100.0);
  return o;
}

}  // namespace giocal
