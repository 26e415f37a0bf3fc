// Error models applied to exact IMU and odometer values: biases (turn-on and random walk), white
// noise, scale and misalignment for the IMU; scale factors, noise, drift and quantization for the
// odometer.
#pragma once

#include <Eigen/Core>
#include <random>

#include "common/imu/imu_sample.h"
#include "common/math/so3.h"
#include "common/odometer/odom_sample.h"
#include "sim/sim_config.h"

namespace giocal::sim {

class ImuErrors {
 public:
  /// Draws the turn-on biases, scale and misalignment from `rng`.
  ImuErrors(const ImuErrorSpec& spec, std::mt19937_64& rng);
  /// Measured sample from true rate and specific force; advances the bias random walks by dt.
  ImuSample measure(double t, const Eigen::Vector3d& gyro, const Eigen::Vector3d& acc, double dt,
                    std::mt19937_64& rng);
  const Eigen::Vector3d& gyroBias() const { return b_g_; }
  const Eigen::Vector3d& accelBias() const { return b_a_; }
  /// The rotation from the ideal IMU axes b to the measuring axes the estimators calibrate
  /// against: the mean of the gyro triad's and the accelerometer triad's misalignment rotations
  /// (roll and pitch of the extrinsic are seen through both; docs/design.md "IMU axes").
  Eigen::Matrix3d measuringAxes() const { return expSO3(0.5 * (logSO3(R_a_b_) + logSO3(R_g_b_))); }
  /// The gyro triad's tilt against the accelerometer's (GyroTilt) [rad]: x and y of
  /// Log(R_g_b R_a_b^T); the two triads lie at +-half of it about the measuring axes.
  Eigen::Vector2d gyroTilt() const { return logSO3(R_g_b_ * R_a_b_.transpose()).head<2>(); }

 private:
  ImuErrorSpec spec_;
  Eigen::Vector3d b_g_, b_a_;
  Eigen::Matrix3d T_g_, T_a_;      // scale and misalignment: measured = T * true
  Eigen::Matrix3d R_a_b_, R_g_b_;  // the rotations in T_a and T_g
};

class OdometerErrors {
 public:
  /// `slip_seed` draws the slip events apart from the noise: a drive with slip has the same
  /// noise as the drive without it (the fault bench compares the two).
  OdometerErrors(const OdometerErrorSpec& spec, double s_v, double s_w, std::uint64_t slip_seed)
      : spec_(spec), s_v_(s_v), s_w_(s_w), slip_rng_(slip_seed) {}
  /// measured = true / (1 + s) + noise, quantized; the scales drift as random walks; while the
  /// wheels slip (Poisson events while driving) the measured speed is slip_speed_factor too high.
  OdomSample measure(double t, double speed, double yaw_rate, double dt, std::mt19937_64& rng);
  double sV() const { return s_v_; }
  double sW() const { return s_w_; }
  int slipEvents() const { return slip_events_; }

 private:
  OdometerErrorSpec spec_;
  double s_v_, s_w_;
  std::mt19937_64 slip_rng_;
  double slip_left_ = 0.0;  // time left in the current wheel-slip event [s]
  int slip_events_ = 0;
};

}  // namespace giocal::sim
