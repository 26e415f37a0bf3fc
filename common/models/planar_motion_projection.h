// PlanarMotionProjection: a model of planar vehicle motion made blind, by construction, to moves
// of p_b_m along the vehicle's vertical axis (R_b_m e_z in b). In planar motion no measurement
// sees that direction (the paper's observability result), but a Jacobian evaluated at a noisy or
// wrong estimate does, and an estimator then gains information it does not have (an
// observability-constrained update: the p_b_m Jacobian is projected onto the observable plane).
#pragma once

#include "common/models/projected_model.h"

namespace giocal {

class PlanarMotionProjection : public ProjectedModel {
 public:
  /// `inner` must have p_b_m and q_b_m blocks. Throws std::invalid_argument otherwise.
  explicit PlanarMotionProjection(std::shared_ptr<const MeasurementModel> inner);

 protected:
  /// The p_b_m Jacobian times (I - u u^T), u = R_b_m e_z.
  void project(const double* const* params, std::vector<Eigen::MatrixXd>& J) const override;

 private:
  int p_block_ = -1, q_block_ = -1;
};

}  // namespace giocal
