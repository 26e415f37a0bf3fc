// RandomWalkModel: a vector state that drifts as a random walk between two epochs (odometer
// scales, receiver clock drift): residual = x_j - x_i with covariance q^2 dt; or, with a decay
// phi = exp(-dt / tau), as a first-order Gauss-Markov process: residual = x_j - phi x_i with
// covariance (1 - phi^2) times its stationary covariance.
#pragma once

#include <string>

#include "common/models/measurement_model.h"

namespace giocal {

class RandomWalkModel : public MeasurementModel {
 public:
  /// `key`: the state; size: its dimension; sigma = q sqrt(dt).
  RandomWalkModel(const StateKey& key, int size, double sigma);
  /// A Gauss-Markov process: `covariance` is that of the residual, (1 - decay^2) Q.
  RandomWalkModel(const StateKey& key, double decay, const Eigen::MatrixXd& covariance);
  std::string name() const override { return "random_walk"; }
  /// key@i, key@j
  const std::vector<StateBlock>& blocks() const override { return blocks_; }
  int residualSize() const override { return size_; }
  void evaluate(const double* const* params, Eigen::VectorXd& residual,
                std::vector<Eigen::MatrixXd>* jacobians) const override;
  Eigen::MatrixXd covariance() const override;

 private:
  std::vector<StateBlock> blocks_;
  int size_;
  Eigen::MatrixXd covariance_;
  double decay_ = 1.0;
};

}  // namespace giocal
