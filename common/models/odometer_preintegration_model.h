// OdometerPreintegrationModel: the integral odometer residual between two IMU poses, through the
// scale factors (those of state i) and the extrinsic.
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
  Eigen::MatrixXd covariance() const override { return pre_->covariance(); }

 private:
  std::shared_ptr<const OdometerPreintegration> pre_;
};

}  // namespace giocal
