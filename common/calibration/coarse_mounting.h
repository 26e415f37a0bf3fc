// CoarseMounting: the IMU's mounting R_b_m found from a drive's IMU and odometer logs alone, for an
// initial guess when none is given: the mean specific force of level driving gives the vehicle's up
// axis in b, and the specific force against the odometer's along-track (dv/dt) and centripetal
// (v w) accelerations gives its forward axis.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "common/imu/imu_sample.h"
#include "common/odometer/odom_sample.h"

namespace giocal {

struct CoarseMounting {
  bool valid = false;
  std::string why_not;  // when not valid
  Eigen::Quaterniond q_b_m = Eigen::Quaterniond::Identity();
  Eigen::Vector3d sigma_rpy = Eigen::Vector3d::Zero();  // 1-sigma of roll, pitch, yaw [rad]
  double yaw_rate_slope = 0.0;  // gyro about the found up axis over the odometer's yaw rate
  int windows = 0;              // odometer intervals used
};

/// Needs a drive with speed changes or turns (at least a few m/s^2 of total acceleration summed
/// over the windows); both logs in rising time.
CoarseMounting estimateMounting(const std::vector<ImuSample>& imu,
                                const std::vector<OdomSample>& odom);

}  // namespace giocal
