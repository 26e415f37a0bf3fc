// NhcModel: the non-holonomic constraint, zero lateral and vertical velocity of the vehicle frame
// m, seen through the IMU state and the extrinsic.
#pragma once

#include <Eigen/Core>

#include "common/models/measurement_model.h"

namespace giocal {

class NhcModel : public MeasurementModel {
 public:
  /// gyro: the raw IMU rate at the constraint's time; sigma: lateral/vertical speed noise [m/s].
  NhcModel(const Eigen::Vector3d& gyro, double sigma) : gyro_(gyro), sigma_(sigma) {}
  std::string name() const override { return "nhc"; }
  /// v_n_b, q_n_b, b_g, p_b_m, q_b_m
  const std::vector<StateBlock>& blocks() const override;
  int residualSize() const override { return 2; }
  void evaluate(const double* const* params, Eigen::VectorXd& residual,
                std::vector<Eigen::MatrixXd>* jacobians) const override;
  Eigen::MatrixXd covariance() const override;
  void covarianceInto(Eigen::MatrixXd& R) const override;

 private:
  Eigen::Vector3d gyro_;
  double sigma_;
};

}  // namespace giocal
