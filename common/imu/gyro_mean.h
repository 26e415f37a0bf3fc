// meanGyro(): the mean raw rate over a window of IMU samples and the variance of that mean, for
// models that take a rate as input (a single noisy sample would bias them: errors in variables).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "common/imu/imu_sample.h"

namespace giocal {

struct GyroMean {
  Eigen::Vector3d rate = Eigen::Vector3d::Zero();
  double variance = 0.0;  // per axis [rad^2/s^2]
};

/// Samples within [t - half_window, t + half_window] (at least the one nearest t); density is the
/// gyro's white noise [rad/s/sqrt(Hz)]. `imu` must be sorted by time and not empty.
GyroMean meanGyro(const std::vector<ImuSample>& imu, double t, double half_window, double density);

}  // namespace giocal
