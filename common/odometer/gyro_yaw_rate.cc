#include "common/odometer/gyro_yaw_rate.h"

#include <algorithm>

namespace giocal {

double gyroYawRate(const std::vector<ImuSample>& imu, double t, const OdometerCalibration& calib,
                   const Eigen::Vector3d& b_g) {
  const auto end = std::upper_bound(imu.begin(), imu.end(), t,
                                    [](double x, const ImuSample& s) { return x < s.t; });
  if (end == imu.begin()) return 0.0;
  const Eigen::Vector3d up_b = calib.q_b_m * Eigen::Vector3d::UnitZ();
  return up_b.dot(std::prev(end)->gyro - b_g) / (1.0 + calib.s_w);
}

}  // namespace giocal
