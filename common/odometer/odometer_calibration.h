// The IMU-odometer parameters giocal calibrates: scale factors and the extrinsic T_b_m.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace giocal {

struct OdometerCalibration {
  double s_v = 0.0;                                 // true speed = (1 + s_v) * measured
  double s_w = 0.0;                                 // true yaw rate = (1 + s_w) * measured
  Eigen::Vector3d p_b_m = Eigen::Vector3d::Zero();  // vehicle origin in b [m]
  Eigen::Quaterniond q_b_m = Eigen::Quaterniond::Identity();  // maps m vectors into b
};

}  // namespace giocal
