#include "common/models/random_walk_model.h"

namespace giocal {

RandomWalkModel::RandomWalkModel(const StateKey& key, int size, double sigma)
    : blocks_{vectorBlock(at(key, Copy::kI), size), vectorBlock(at(key, Copy::kJ), size)},
      size_(size),
      covariance_(Eigen::MatrixXd::Identity(size, size) * sigma * sigma) {}

RandomWalkModel::RandomWalkModel(const StateKey& key, double decay,
                                 const Eigen::MatrixXd& covariance)
    : blocks_{vectorBlock(at(key, Copy::kI), static_cast<int>(covariance.rows())),
              vectorBlock(at(key, Copy::kJ), static_cast<int>(covariance.rows()))},
      size_(static_cast<int>(covariance.rows())),
      covariance_(covariance),
      decay_(decay) {}

void RandomWalkModel::evaluate(const double* const* params, Eigen::VectorXd& residual,
                               std::vector<Eigen::MatrixXd>* jacobians) const {
  residual = Eigen::Map<const Eigen::VectorXd>(params[1], size_) -
             decay_ * Eigen::Map<const Eigen::VectorXd>(params[0], size_);
  if (jacobians) {
    *jacobians = {-decay_ * Eigen::MatrixXd::Identity(size_, size_),
                  Eigen::MatrixXd::Identity(size_, size_)};
  }
}

Eigen::MatrixXd RandomWalkModel::covariance() const { return covariance_; }

}  // namespace giocal
