#include "common/models/heading_change_model.h"

#include <cmath>

#include "common/math/so3.h"
#include "common/models/block_values.h"

namespace giocal {
namespace {

/// Yaw of R and its gradient for a right perturbation R Exp(theta): the first column c0 of R moves
/// by -R [e1]x theta and yaw = atan2(c0.y, c0.x).
double yawOf(const Eigen::Matrix3d& R, Eigen::RowVector3d* d_theta) {
  const double x = R(0, 0), y = R(1, 0);
  if (d_theta) {
    const double n2 = x * x + y * y;
    const Eigen::RowVector3d d_c0(-y / n2, x / n2, 0.0);
    *d_theta = -d_c0 * R * skew(Eigen::Vector3d::UnitX());
  }
  return std::atan2(y, x);
}

}  // namespace

const std::vector<StateBlock>& HeadingChangeModel::blocks() const {
  static const std::vector<StateBlock> kBlocks{rotationBlock(at(state::kQ, Copy::kI)),
                                               rotationBlock(at(state::kQ, Copy::kJ))};
  return kBlocks;
}

void HeadingChangeModel::evaluate(const double* const* params, Eigen::VectorXd& residual,
                                  std::vector<Eigen::MatrixXd>* jacobians) const {
  Eigen::RowVector3d Ji, Jj;
  const double yi = yawOf(quatAt(params[0]).toRotationMatrix(), &Ji);
  const double yj = yawOf(quatAt(params[1]).toRotationMatrix(), &Jj);
  residual.resize(1);
  residual[0] = std::remainder(yj - yi, 2.0 * M_PI);
  if (jacobians) *jacobians = {-Ji, Jj};
}

Eigen::MatrixXd HeadingChangeModel::covariance() const {
  return Eigen::MatrixXd::Constant(1, 1, sigma_ * sigma_);
}

}  // namespace giocal
