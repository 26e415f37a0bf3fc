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

#include "common/io/dataset_description.h"
#include "common/io/model_options.h"
#include "common/models/measurement_model.h"
#include "common/odometer/odometer_preintegration.h"

namespace giocal {

class OdometerPreintegrationModel : public MeasurementModel {
 public:
  /// position_only: a speed-only odometer, whose heading change was taken from the gyro: only
  /// the position rows are a measurement, evaluated at the s_w of the interval's start (the
  /// s_w block is not seen; its Jacobian is zero).
  explicit OdometerPreintegrationModel(std::shared_ptr<const OdometerPreintegration> pre,
                                       bool position_only = false)
      : pre_(std::move(pre)), rows_(position_only ? 3 : 6) {}
  std::string name() const override {
    return rows_ == 6 ? "odometer_preintegration" : "odometer_speed_preintegration";
  }
  /// p@i, q@i, p@j, q@j, s_v@i, s_w@i, p_b_m, q_b_m
  const std::vector<StateBlock>& blocks() const override;
  int residualSize() const override { return rows_; }
  void evaluate(const double* const* params, Eigen::VectorXd& residual,
                std::vector<Eigen::MatrixXd>* jacobians) const override;
  Eigen::MatrixXd covariance() const override { return Eigen::MatrixXd::Identity(rows_, rows_); }

 private:
  /// W with W^T W = covariance^-1 (of the rows in use) at these scales.
  Eigen::MatrixXd whitenerAt(double s_v, double s_w) const;
  std::shared_ptr<const OdometerPreintegration> pre_;
  int rows_;
};

/// The integral measurement's noise: the odometer's own, and the models' out-of-plane noise.
OdometerPreintegrationNoise odometerPreintegrationNoise(const OdometerNoise& odometer,
                                                        const ModelOptions& models);

}  // namespace giocal
