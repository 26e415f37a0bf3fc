// gyroYawRate: the yaw rate a speed-only odometer is given, the gyro's turn rate about the
// vehicle's up axis, so that its speed can be integrated along the heading the IMU measures.
#pragma once

#include <vector>

#include "common/imu/imu_sample.h"
#include "common/odometer/odometer_calibration.h"

namespace giocal {

/// The newest gyro sample at or before t (an online calibrator has no later one yet) about
/// R_b_m e_z, divided by 1 + s_w of `calib` so that the integral measurement, which multiplies
/// it by 1 + s_w, turns by what the gyro measured; 0 when no sample is at or before t.
/// b_g: the gyro bias known so far (an MTi-30's 0.1 deg/s turns the heading by 1.7 mrad over a
/// 1 s odometer interval).
double gyroYawRate(const std::vector<ImuSample>& imu, double t, const OdometerCalibration& calib,
                   const Eigen::Vector3d& b_g = Eigen::Vector3d::Zero());

}  // namespace giocal
