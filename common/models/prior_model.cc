#include "common/models/prior_model.h"

#include <stdexcept>

#include "common/math/rotation.h"
#include "common/models/block_values.h"

namespace giocal {

PriorModel::PriorModel(std::vector<StateBlock> blocks, Eigen::VectorXd mean,
                       Eigen::MatrixXd covariance)
    : blocks_(std::move(blocks)), mean_(std::move(mean)), covariance_(std::move(covariance)) {
  int ambient = 0, tangent = 0;
  for (const auto& b : blocks_) {
    ambient += b.ambientSize();
    tangent += b.tangentSize();
  }
  if (mean_.size() != ambient || covariance_.rows() != tangent || covariance_.cols() != tangent) {
    throw std::invalid_argument("PriorModel: mean or covariance size does not match the blocks");
  }
}

void PriorModel::evaluate(const double* const* params, Eigen::VectorXd& residual,
                          std::vector<Eigen::MatrixXd>* jacobians) const {
  residual.resize(residualSize());
  if (jacobians) jacobians->clear();
  int a = 0, t = 0;
  for (size_t k = 0; k < blocks_.size(); ++k) {
    const StateBlock& b = blocks_[k];
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(residualSize(), b.tangentSize());
    if (b.kind == BlockKind::kRotation) {
      const Vec3 r = boxMinus(quatAt(params[k]), quatFromWxyz(mean_.data() + a));
      residual.segment<3>(t) = r;
      J.block<3, 3>(t, 0) = rightJacobianInvSO3(r);
    } else {
      residual.segment(t, b.size) =
          Eigen::Map<const Eigen::VectorXd>(params[k], b.size) - mean_.segment(a, b.size);
      J.block(t, 0, b.size, b.size).setIdentity();
    }
    if (jacobians) jacobians->push_back(J);
    a += b.ambientSize();
    t += b.tangentSize();
  }
}

}  // namespace giocal
