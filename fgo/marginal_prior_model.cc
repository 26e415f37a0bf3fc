#include "fgo/marginal_prior_model.h"

#include "common/math/rotation.h"

namespace giocal {

MarginalPriorModel::MarginalPriorModel(std::vector<StateBlock> blocks, Eigen::VectorXd x_lin,
                                       Eigen::MatrixXd J, Eigen::VectorXd r0)
    : blocks_(std::move(blocks)), x_lin_(std::move(x_lin)), J_(std::move(J)), r0_(std::move(r0)) {}

void MarginalPriorModel::evaluate(const double* const* params, Eigen::VectorXd& residual,
                                  std::vector<Eigen::MatrixXd>* jacobians) const {
  Eigen::VectorXd dx(J_.cols());
  int a = 0, t = 0;
  for (size_t k = 0; k < blocks_.size(); ++k) {
    const StateBlock& b = blocks_[k];
    if (b.kind == BlockKind::kRotation) {
      // The first-estimate Jacobian is kept for the rotation's tangent too (no Jr^-1 update).
      dx.segment<3>(t) = boxMinus(quatFromWxyz(params[k]), quatFromWxyz(x_lin_.data() + a));
    } else {
      dx.segment(t, b.size) =
          Eigen::Map<const Eigen::VectorXd>(params[k], b.size) - x_lin_.segment(a, b.size);
    }
    a += b.ambientSize();
    t += b.tangentSize();
  }
  residual = r0_ + J_ * dx;
  if (jacobians) {
    jacobians->clear();
    t = 0;
    for (const StateBlock& b : blocks_) {
      jacobians->push_back(J_.middleCols(t, b.tangentSize()));
      t += b.tangentSize();
    }
  }
}

}  // namespace giocal
