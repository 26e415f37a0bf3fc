// OdometerVelocityModel: one odometer sample (forward speed and yaw rate of m) predicted from the
// IMU state, the scale factors and the extrinsic; for a filter updating at the odometer rate.
#pragma once

#include <Eigen/Core>

#include "common/models/measurement_model.h"
#include "common/odometer/odom_sample.h"

namespace giocal {

class OdometerVelocityModel : public MeasurementModel {
 public:
  /// gyro: the raw IMU rate at the sample's time. Sigmas of the measured speed [m/s] and yaw
  /// rate [rad/s].
  OdometerVelocityModel(const OdomSample& sample, const Eigen::Vector3d& gyro, double speed_sigma,
                        double yaw_rate_sigma)
      : sample_(sample), gyro_(gyro), speed_sigma_(speed_sigma), yaw_rate_sigma_(yaw_rate_sigma) {}
  std::string name() const override { return "odometer_velocity"; }
  /// v_n_b, q_n_b, b_g, s_v, s_w, p_b_m, q_b_m
  const std::vector<StateBlock>& blocks() const override;
  int residualSize() const override { return 2; }
  /// residual = [v_m,y / (1 + s_v) - v, w_m,z / (1 + s_w) - w]: measured = true / (1 + s).
  void evaluate(const double* const* params, Eigen::VectorXd& residual,
                std::vector<Eigen::MatrixXd>* jacobians) const override;
  Eigen::MatrixXd covariance() const override;

 private:
  OdomSample sample_;
  Eigen::Vector3d gyro_;
  double speed_sigma_, yaw_rate_sigma_;
};

}  // namespace giocal
