// Velocity of the vehicle origin expressed in the vehicle frame m, predicted from the IMU state and
// the extrinsic: v_m = R_m_b (R_n_b^T v_n_b + w_b x p_b_m). Shared by the odometer and NHC models.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace giocal {

struct VehicleVelocity {
  Eigen::Vector3d v_m;  // [m/s], x right, y forward, z up
  Eigen::Vector3d w_m;  // angular rate of m in m [rad/s]
  // Jacobians of v_m and w_m with respect to the right-perturbed blocks.
  Eigen::Matrix3d dv_dv_n, dv_dq_n_b, dv_dbg, dv_dp_b_m, dv_dq_b_m;
  Eigen::Matrix3d dw_dbg, dw_dq_b_m;
};

/// gyro is the raw IMU rate; w_b = gyro - b_g (Earth rotation, 7e-5 rad/s, is below the lever-arm
/// term's resolution and left out).
VehicleVelocity vehicleVelocity(const Eigen::Vector3d& v_n_b, const Eigen::Quaterniond& q_n_b,
                                const Eigen::Vector3d& gyro, const Eigen::Vector3d& b_g,
                                const Eigen::Vector3d& p_b_m, const Eigen::Quaterniond& q_b_m);

}  // namespace giocal
