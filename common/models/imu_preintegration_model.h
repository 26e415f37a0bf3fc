// ImuPreintegrationModel: the IMU preintegration residual between two navigation states.
#pragma once

#include <memory>

#include "common/imu/imu_preintegration.h"
#include "common/models/measurement_model.h"

namespace giocal {

class ImuPreintegrationModel : public MeasurementModel {
 public:
  /// `with_tilt`: the gyro triad's tilt (GyroTilt) is a block of the model too.
  explicit ImuPreintegrationModel(std::shared_ptr<const ImuPreintegration> pre,
                                  bool with_tilt = false)
      : pre_(std::move(pre)), with_tilt_(with_tilt) {}
  std::string name() const override { return "imu_preintegration"; }
  /// p, q, v, b_a, b_g of state i, then of state j ("@i", "@j")[, the gyro tilt].
  const std::vector<StateBlock>& blocks() const override;
  int residualSize() const override { return 15; }
  void evaluate(const double* const* params, Eigen::VectorXd& residual,
                std::vector<Eigen::MatrixXd>* jacobians) const override;
  Eigen::MatrixXd covariance() const override { return pre_->covariance(); }

 private:
  std::shared_ptr<const ImuPreintegration> pre_;
  bool with_tilt_ = false;
};

}  // namespace giocal
