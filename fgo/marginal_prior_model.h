// MarginalPriorModel: what marginalization leaves of the removed states, a linear prior on the
// kept blocks, residual = r0 + J (x (-) x_lin), with J and r0 fixed at the first estimate x_lin
// (first-estimate Jacobians keep the window from gaining information it does not have).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "common/models/measurement_model.h"

namespace giocal {

class MarginalPriorModel : public MeasurementModel {
 public:
  /// x_lin: the blocks' ambient values back to back; J has one column per tangent dimension.
  MarginalPriorModel(std::vector<StateBlock> blocks, Eigen::VectorXd x_lin, Eigen::MatrixXd J,
                     Eigen::VectorXd r0);
  std::string name() const override { return "marginal_prior"; }
  const std::vector<StateBlock>& blocks() const override { return blocks_; }
  int residualSize() const override { return static_cast<int>(r0_.size()); }
  void evaluate(const double* const* params, Eigen::VectorXd& residual,
                std::vector<Eigen::MatrixXd>* jacobians) const override;
  /// The residual is already whitened.
  Eigen::MatrixXd covariance() const override {
    return Eigen::MatrixXd::Identity(residualSize(), residualSize());
  }

 private:
  std::vector<StateBlock> blocks_;
  Eigen::VectorXd x_lin_;
  Eigen::MatrixXd J_;
  Eigen::VectorXd r0_;
};

}  // namespace giocal
