// RandomWalkModel: a vector state that drifts as a random walk between two epochs (odometer
// scales, receiver clock drift): residual = x_j - x_i with covariance q^2 dt.
#pragma once

#include <string>

#include "common/models/measurement_model.h"

namespace giocal {

class RandomWalkModel : public MeasurementModel {
 public:
  /// `key`: the state; size: its dimension; sigma = q sqrt(dt).
  RandomWalkModel(const StateKey& key, int size, double sigma);
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
  double sigma_;
};

}  // namespace giocal
