// ImuPreintegrationModel: the IMU preintegration residual between two navigation states.
#pragma once

#include <memory>

#include "common/imu/imu_preintegration.h"
#include "common/models/measurement_model.h"

namespace giocal {

class ImuPreintegrationModel : public MeasurementModel {
 public:
  explicit ImuPreintegrationModel(std::shared_ptr<const ImuPreintegration> pre)
      : pre_(std::move(pre)) {}
  std::string name() const override { return "imu_preintegration"; }
  /// p, q, v, b_a, b_g of state i, then of state j ("@i", "@j").
  const std::vector<StateBlock>& blocks() const override;
  int residualSize() const override { return 15; }
  void evaluate(const double* const* params, Eigen::VectorXd& residual,
                std::vector<Eigen::MatrixXd>* jacobians) const override;
  Eigen::MatrixXd covariance() const override { return pre_->covariance(); }

 private:
  std::shared_ptr<const ImuPreintegration> pre_;
};

}  // namespace giocal
