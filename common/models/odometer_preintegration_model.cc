#include "common/models/odometer_preintegration_model.h"

#include "common/math/whitening.h"
#include "common/models/block_values.h"

namespace giocal {

const std::vector<StateBlock>& OdometerPreintegrationModel::blocks() const {
  static const std::vector<StateBlock> kBlocks{vectorBlock(block::at(block::kP, 'i')),
                                               rotationBlock(block::at(block::kQ, 'i')),
                                               vectorBlock(block::at(block::kP, 'j')),
                                               rotationBlock(block::at(block::kQ, 'j')),
                                               vectorBlock(block::at(block::kSv, 'i'), 1),
                                               vectorBlock(block::at(block::kSw, 'i'), 1),
                                               vectorBlock(block::kPbm),
                                               rotationBlock(block::kQbm)};
  return kBlocks;
}

Eigen::Matrix<double, 6, 6> OdometerPreintegrationModel::whitenerAt(double s_v, double s_w) const {
  return whitener(pre_->covarianceAt(s_v, s_w), name());
}

void OdometerPreintegrationModel::evaluate(const double* const* params, Eigen::VectorXd& residual,
                                           std::vector<Eigen::MatrixXd>* jacobians) const {
  OdometerCalibration c;
  c.s_v = params[4][0];
  c.s_w = params[5][0];
  c.p_b_m = vec3At(params[6]);
  c.q_b_m = quatAt(params[7]);
  const OdometerResidual r =
      pre_->evaluate(vec3At(params[0]), quatAt(params[1]), vec3At(params[2]), quatAt(params[3]), c);
  const Eigen::Matrix<double, 6, 6> W = whitenerAt(c.s_v, c.s_w);
  residual = W * r.r;
  if (jacobians) {
    *jacobians = {W * r.J_p_i, W * r.J_q_i, W * r.J_p_j,   W * r.J_q_j,
                  W * r.J_s_v, W * r.J_s_w, W * r.J_p_b_m, W * r.J_q_b_m};
    // The whitening's own dependence on the scales (central differences: W is smooth and cheap).
    const double h = 1e-6;
    (*jacobians)[4] +=
        (whitenerAt(c.s_v + h, c.s_w) - whitenerAt(c.s_v - h, c.s_w)) * r.r / (2 * h);
    (*jacobians)[5] +=
        (whitenerAt(c.s_v, c.s_w + h) - whitenerAt(c.s_v, c.s_w - h)) * r.r / (2 * h);
  }
}

}  // namespace giocal
