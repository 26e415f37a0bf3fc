// ZuptModel: zero velocity of the IMU in n while the robot stands still.
#pragma once

#include "common/models/measurement_model.h"

namespace giocal {

class ZuptModel : public MeasurementModel {
 public:
  explicit ZuptModel(double sigma) : sigma_(sigma) {}
  std::string name() const override { return "zupt"; }
  const std::vector<StateBlock>& blocks() const override;
  int residualSize() const override { return 3; }
  void evaluate(const double* const* params, Eigen::VectorXd& residual,
                std::vector<Eigen::MatrixXd>* jacobians) const override;
  Eigen::MatrixXd covariance() const override;

 private:
  double sigma_;  // [m/s]
};

}  // namespace giocal
