// OdometerPreintegrationModel: the integral odometer residual between two IMU poses, through the
// scale factors (those of state i) and the extrinsic, whitened by its covariance at the current
// scales (covariance() is the identity).
//
// Why whitened here: the measured speed and yaw rate are noisy and multiplied by the unknown
// (1 + s). Least squares with a fixed weight then shrinks the scales by about
// sigma^2 / E[(int w dt)^2] (regression dilution, errors in variables); with the weight at the
// current scales the cost is the profile likelihood over the true readings, which is unbiased
// (docs/results.md: field preset, W scale).
#pragma once

#include <memory>

#include "common/models/measurement_model.h"
#include "common/odometer/odometer_preintegration.h"

namespace giocal {

class OdometerPreintegrationModel : public MeasurementModel {
 public:
  explicit OdometerPreintegrationModel(std::shared_ptr<const OdometerPreintegration> pre)
      : pre_(std::move(pre)) {}
  std::string name() const override { return "odometer_preintegration"; }
  /// p@i, q@i, p@j, q@j, s_v@i, s_w@i, p_b_m, q_b_m
  const std::vector<StateBlock>& blocks() const override;
  int residualSize() const override { return 6; }
  void evaluate(const double* const* params, Eigen::VectorXd& residual,
                std::vector<Eigen::MatrixXd>* jacobians) const override;
  Eigen::MatrixXd covariance() const override { return Eigen::MatrixXd::Identity(6, 6); }

 private:
  /// W with W^T W = covariance^-1 at these scales.
  Eigen::Matrix<double, 6, 6> whitenerAt(double s_v, double s_w) const;
  std::shared_ptr<const OdometerPreintegration> pre_;
};

}  // namespace giocal
