#include "common/models/imu_preintegration_model.h"

#include "common/models/block_values.h"

namespace giocal {

const std::vector<StateBlock>& ImuPreintegrationModel::blocks() const {
  static const std::vector<StateBlock> kBlocks = [] {
    std::vector<StateBlock> b;
    for (Copy e : {Copy::kI, Copy::kJ}) {
      b.push_back(vectorBlock(at(state::kP, e)));
      b.push_back(rotationBlock(at(state::kQ, e)));
      b.push_back(vectorBlock(at(state::kV, e)));
      b.push_back(vectorBlock(at(state::kBa, e)));
      b.push_back(vectorBlock(at(state::kBg, e)));
    }
    return b;
  }();
  static const std::vector<StateBlock> kWithTilt = [] {
    std::vector<StateBlock> b = kBlocks;
    b.push_back(vectorBlock(state::kGyroTilt, 2));
    return b;
  }();
  return with_tilt_ ? kWithTilt : kBlocks;
}

void ImuPreintegrationModel::evaluate(const double* const* params, Eigen::VectorXd& residual,
                                      std::vector<Eigen::MatrixXd>* jacobians) const {
  auto state = [&](int o) {
    NavState s;
    s.p_n_b = vec3At(params[o]);
    s.q_n_b = quatAt(params[o + 1]);
    s.v_n_b = vec3At(params[o + 2]);
    s.b_a = vec3At(params[o + 3]);
    s.b_g = vec3At(params[o + 4]);
    return s;
  };
  std::optional<GyroTilt> tilt;
  if (with_tilt_) tilt = GyroTilt(params[10][0], params[10][1]);
  const ImuResidual r = pre_->evaluate(state(0), state(5), tilt);
  residual = r.r;
  if (jacobians) {
    *jacobians = {r.J_p_i, r.J_q_i, r.J_v_i, r.J_ba_i, r.J_bg_i,
                  r.J_p_j, r.J_q_j, r.J_v_j, r.J_ba_j, r.J_bg_j};
    if (with_tilt_) jacobians->push_back(r.J_tilt);
  }
}

}  // namespace giocal
