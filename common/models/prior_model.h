// PriorModel: a Gaussian prior on a set of blocks, residual = x (-) mean (right-perturbation
// difference for rotations).
#pragma once

#include <Eigen/Core>

#include "common/models/measurement_model.h"

namespace giocal {

class PriorModel : public MeasurementModel {
 public:
  /// mean holds the blocks' ambient values back to back; covariance is over their tangent spaces.
  PriorModel(std::vector<StateBlock> blocks, Eigen::VectorXd mean, Eigen::MatrixXd covariance);
  std::string name() const override { return "prior"; }
  const std::vector<StateBlock>& blocks() const override { return blocks_; }
  int residualSize() const override { return static_cast<int>(covariance_.rows()); }
  void evaluate(const double* const* params, Eigen::VectorXd& residual,
                std::vector<Eigen::MatrixXd>* jacobians) const override;
  Eigen::MatrixXd covariance() const override { return covariance_; }

 private:
  std::vector<StateBlock> blocks_;
  Eigen::VectorXd mean_;
  Eigen::MatrixXd covariance_;
};

}  // namespace giocal
