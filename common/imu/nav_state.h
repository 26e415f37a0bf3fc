// NavState: IMU position, velocity and attitude in the local ENU frame n, with the IMU biases.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace giocal {

struct NavState {
  double t = 0.0;
  Eigen::Vector3d p_n_b = Eigen::Vector3d::Zero();
  Eigen::Vector3d v_n_b = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_n_b = Eigen::Quaterniond::Identity();
  Eigen::Vector3d b_a = Eigen::Vector3d::Zero();  // accelerometer bias [m/s^2]
  Eigen::Vector3d b_g = Eigen::Vector3d::Zero();  // gyro bias [rad/s]
};

}  // namespace giocal
