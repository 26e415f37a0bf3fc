#include "common/models/zupt_model.h"

#include "common/models/block_values.h"

namespace giocal {

const std::vector<StateBlock>& ZuptModel::blocks() const {
  static const std::vector<StateBlock> kBlocks{vectorBlock(state::kV)};
  return kBlocks;
}

void ZuptModel::evaluate(const double* const* params, Eigen::VectorXd& residual,
                         std::vector<Eigen::MatrixXd>* jacobians) const {
  residual = vec3At(params[0]);
  if (jacobians) *jacobians = {Eigen::Matrix3d::Identity()};
}

Eigen::MatrixXd ZuptModel::covariance() const {
  return Eigen::Matrix3d::Identity() * sigma_ * sigma_;
}

}  // namespace giocal
