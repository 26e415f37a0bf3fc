// One IMU sample: angular rate [rad/s] and specific force [m/s^2] in the body frame b.
#pragma once

#include <Eigen/Core>

namespace giocal {

struct ImuSample {
  double t = 0.0;  // GPS seconds
  Eigen::Vector3d gyro = Eigen::Vector3d::Zero();
  Eigen::Vector3d acc = Eigen::Vector3d::Zero();
};

}  // namespace giocal
