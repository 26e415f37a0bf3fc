#include "common/calibration/warm_start.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/math/rotation.h"

namespace giocal {

namespace {
constexpr double kLeverArmTolerance = 0.01;  // [m] the same GNSS lever arm, measured again
}  // namespace

std::map<std::string, double> robotFingerprint(const DatasetDescription& d) {
  return {{"p_b_g.x", d.p_b_g.x()},
          {"p_b_g.y", d.p_b_g.y()},
          {"p_b_g.z", d.p_b_g.z()},
          {"imu.gyro_noise_density", d.imu_noise.gyro_noise_density},
          {"imu.accel_noise_density", d.imu_noise.accel_noise_density},
          {"imu.gyro_bias_random_walk", d.imu_noise.gyro_bias_random_walk},
          {"imu.accel_bias_random_walk", d.imu_noise.accel_bias_random_walk},
          {"odometer.speed_sigma", d.odom_noise.speed_sigma},
          {"odometer.yaw_rate_sigma", d.odom_noise.yaw_rate_sigma},
          {"odometer.measures_yaw_rate", d.odom_noise.measures_yaw_rate ? 1.0 : 0.0}};
}

std::string robotMismatch(const std::map<std::string, double>& earlier,
                          const std::map<std::string, double>& now) {
  for (const auto& [key, value] : now) {
    const auto it = earlier.find(key);
    char text[160];
    if (it == earlier.end()) return key + " (missing in the earlier run)";
    // A lever arm measured again differs by millimetres; the noise values are copied as written.
    const double tolerance =
        key.rfind("p_b_g", 0) == 0 ? kLeverArmTolerance : 1e-9 * std::max(1.0, std::abs(value));
    if (std::abs(it->second - value) > tolerance) {
      std::snprintf(text, sizeof text, " (%.9g in the earlier run, %.9g now)", it->second, value);
      return key + text;
    }
  }
  return "";
}

CalibrationPrior carriedPrior(const CalibrationPrior& earlier, double dt_s,
                              const WarmStartOptions& o) {
  CalibrationPrior p = earlier;
  Eigen::Matrix<double, 8, 8> cov =
      earlier.covariance ? *earlier.covariance : Eigen::Matrix<double, 8, 8>::Zero();
  const double days = std::max(0.0, dt_s) / 86400.0;
  const double q[8] = {o.s_v,
                       o.s_w,
                       o.p_b_m,
                       o.p_b_m,
                       o.p_b_m,
                       o.rpy_deg * kDegToRad,
                       o.rpy_deg * kDegToRad,
                       o.rpy_deg * kDegToRad};
  for (int i = 0; i < 8; ++i) cov(i, i) += q[i] * q[i] * days;
  p.covariance = cov;
  // The sigmas say the same (readers of the prior that look only at them).
  p.sd_s_v = std::sqrt(cov(0, 0));
  p.sd_s_w = std::sqrt(cov(1, 1));
  p.sd_p_b_m = cov.diagonal().segment<3>(2).cwiseSqrt();
  p.sd_rpy_b_m = cov.diagonal().tail<3>().cwiseSqrt();
  return p;
}

}  // namespace giocal
