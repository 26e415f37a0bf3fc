#include "common/models/random_walk_model.h"

namespace giocal {

RandomWalkModel::RandomWalkModel(const StateKey& key, int size, double sigma)
    : blocks_{vectorBlock(at(key, Copy::kI), size), vectorBlock(at(key, Copy::kJ), size)},
      size_(size),
      sigma_(sigma) {}

void RandomWalkModel::evaluate(const double* const* params, Eigen::VectorXd& residual,
                               std::vector<Eigen::MatrixXd>* jacobians) const {
  residual = Eigen::Map<const Eigen::VectorXd>(params[1], size_) -
             Eigen::Map<const Eigen::VectorXd>(params[0], size_);
  if (jacobians) {
    *jacobians = {-Eigen::MatrixXd::Identity(size_, size_),
                  Eigen::MatrixXd::Identity(size_, size_)};
  }
}

Eigen::MatrixXd RandomWalkModel::covariance() const {
  return Eigen::MatrixXd::Identity(size_, size_) * sigma_ * sigma_;
}

}  // namespace giocal
