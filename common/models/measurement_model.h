// MeasurementModel: one measurement's physics, written once: residual, Jacobians with respect to
// named state blocks, and noise. The EKF turns it into H rows, the factor graph into a Ceres cost.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "common/models/state_block.h"

namespace giocal {

class MeasurementModel {
 public:
  virtual ~MeasurementModel() = default;

  virtual std::string name() const = 0;
  /// The blocks the residual depends on, in the order of `params` and of the Jacobians.
  virtual const std::vector<StateBlock>& blocks() const = 0;
  virtual int residualSize() const = 0;

  /// residual = h(x) - z. params[k] holds block k's ambient values. When `jacobians` is given it
  /// receives, per block, d residual / d (tangent perturbation) of size residualSize x tangentSize.
  /// A model may write into the given residual and Jacobians in place (no allocation when a
  /// caller hands back the same ones, sized by the last call).
  virtual void evaluate(const double* const* params, Eigen::VectorXd& residual,
                        std::vector<Eigen::MatrixXd>* jacobians) const = 0;

  /// Covariance of the residual (of the measurement noise).
  virtual Eigen::MatrixXd covariance() const = 0;
  /// The same into R, which a model may fill in place.
  virtual void covarianceInto(Eigen::MatrixXd& R) const { R = covariance(); }
};

}  // namespace giocal
