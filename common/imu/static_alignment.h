// Static alignment: roll and pitch from the mean specific force and the gyro bias from the mean
// rate of a window in which the robot stands still (heading comes from elsewhere: GNSS motion).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "common/imu/imu_sample.h"

namespace giocal {

struct StaticAlignment {
  double roll = 0.0, pitch = 0.0;                             // [rad]
  Eigen::Quaterniond q_n_b = Eigen::Quaterniond::Identity();  // with the given heading
  Eigen::Vector3d b_g = Eigen::Vector3d::Zero();     // mean rate minus the Earth rate [rad/s]
  Eigen::Vector3d sd_b_g = Eigen::Vector3d::Zero();  // 1-sigma of b_g from the rate noise
  double sd_tilt = 0.0;                              // 1-sigma of roll and pitch [rad]
};

/// `window` must hold at least two samples of a robot at rest. `yaw` [rad] fixes the heading
/// (needed only to remove the Earth rate from the gyro mean); `omega_ie_n` is the Earth rate in n.
/// Noise densities (rad/s/sqrt(Hz), m/s^2/sqrt(Hz)) give the reported sigmas.
StaticAlignment alignStatic(const std::vector<ImuSample>& window, double yaw,
                            const Eigen::Vector3d& omega_ie_n, double gyro_noise_density,
                            double accel_noise_density);

/// Combines the alignment's gyro bias (a measurement from the static mean) with a turn-on prior
/// of mean zero and 1-sigma `prior_sigma` [rad/s] per axis: the minimum-variance combination of
/// the two. A prior_sigma of zero or less means "no prior" and leaves the alignment unchanged.
StaticAlignment withGyroBiasPrior(StaticAlignment a, double prior_sigma);

}  // namespace giocal
