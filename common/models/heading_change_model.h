// HeadingChangeModel: the heading measurement constraint (HMC) of a robot standing still: the yaw
// of q_n_b at j equals that at i (the EKF clones the attitude when the robot stops).
#pragma once

#include "common/models/measurement_model.h"

namespace giocal {

class HeadingChangeModel : public MeasurementModel {
 public:
  explicit HeadingChangeModel(double sigma) : sigma_(sigma) {}
  std::string name() const override { return "heading_change"; }
  /// q_n_b@i, q_n_b@j
  const std::vector<StateBlock>& blocks() const override;
  int residualSize() const override { return 1; }
  /// residual = yaw_j - yaw_i wrapped to (-pi, pi], yaw of R = Rz(yaw) Ry(pitch) Rx(roll).
  void evaluate(const double* const* params, Eigen::VectorXd& residual,
                std::vector<Eigen::MatrixXd>* jacobians) const override;
  Eigen::MatrixXd covariance() const override;

 private:
  double sigma_;  // [rad]
};

}  // namespace giocal
