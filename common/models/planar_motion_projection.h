// PlanarMotionProjection: a model of planar vehicle motion made blind, by construction, to moves
// of p_b_m along the vehicle's vertical axis (R_b_m e_z in b). In planar motion no measurement
// sees that direction (the paper's observability result), but a Jacobian evaluated at a noisy or
// wrong estimate does, and an estimator then gains information it does not have (an
// observability-constrained update: the p_b_m Jacobian is projected onto the observable plane).
#pragma once

#include <memory>

#include "common/models/measurement_model.h"

namespace giocal {

class PlanarMotionProjection : public MeasurementModel {
 public:
  /// `inner` must have blocks named p_b_m and q_b_m. Throws std::invalid_argument otherwise.
  explicit PlanarMotionProjection(std::shared_ptr<const MeasurementModel> inner);
  std::string name() const override { return inner_->name() + "+planar"; }
  const std::vector<StateBlock>& blocks() const override { return inner_->blocks(); }
  int residualSize() const override { return inner_->residualSize(); }
  /// The inner residual; the p_b_m Jacobian times (I - u u^T), u = R_b_m e_z.
  void evaluate(const double* const* params, Eigen::VectorXd& residual,
                std::vector<Eigen::MatrixXd>* jacobians) const override;
  Eigen::MatrixXd covariance() const override { return inner_->covariance(); }

 private:
  std::shared_ptr<const MeasurementModel> inner_;
  int p_block_ = -1, q_block_ = -1;
};

}  // namespace giocal
