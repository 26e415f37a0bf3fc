#include "common/models/odometer_preintegration_model.h"

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

void OdometerPreintegrationModel::evaluate(const double* const* params, Eigen::VectorXd& residual,
                                           std::vector<Eigen::MatrixXd>* jacobians) const {
  OdometerCalibration c;
  c.s_v = params[4][0];
  c.s_w = params[5][0];
  c.p_b_m = vec3At(params[6]);
  c.q_b_m = quatAt(params[7]);
  const OdometerResidual r =
      pre_->evaluate(vec3At(params[0]), quatAt(params[1]), vec3At(params[2]), quatAt(params[3]), c);
  residual = r.r;
  if (jacobians) {
    *jacobians = {r.J_p_i, r.J_q_i, r.J_p_j, r.J_q_j, r.J_s_v, r.J_s_w, r.J_p_b_m, r.J_q_b_m};
  }
}

}  // namespace giocal
