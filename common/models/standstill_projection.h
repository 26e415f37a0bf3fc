// StandstillProjection: an odometer interval over which the vehicle stood still, made blind to the
// calibration (s_v, s_w, p_b_m, q_b_m). At the truth a still vehicle's odometer model has zero
// Jacobian in all four (no travel, no turn, no rotation of the lever arm), but at an estimate
// whose IMU rotated by its gyro noise it does not, and an estimator then gains information on the
// extrinsic that it does not have (the same observability-constrained idea as
// PlanarMotionProjection). The residual is unchanged: "no motion" still constrains the pose.
#pragma once

#include "common/models/projected_model.h"

namespace giocal {

class StandstillProjection : public ProjectedModel {
 public:
  /// `inner` must have at least one calibration block. Throws std::invalid_argument otherwise.
  explicit StandstillProjection(std::shared_ptr<const MeasurementModel> inner);

 protected:
  /// Zero Jacobians in the calibration blocks.
  void project(const double* const* params, std::vector<Eigen::MatrixXd>& J) const override;

 private:
  std::vector<size_t> calibration_blocks_;
};

}  // namespace giocal
