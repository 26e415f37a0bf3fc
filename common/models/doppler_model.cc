#include "common/models/doppler_model.h"

#include "common/math/so3.h"
#include "common/models/block_values.h"

namespace giocal {

DopplerModel::DopplerModel(const Eigen::Matrix3d& R_e_n, const Eigen::Vector3d& gyro,
                           std::vector<DopplerObservation> observations)
    : R_e_n_(R_e_n), gyro_(gyro), obs_(std::move(observations)) {}

const std::vector<StateBlock>& DopplerModel::blocks() const {
  static const std::vector<StateBlock> kBlocks{vectorBlock(state::kV), rotationBlock(state::kQ),
                                               vectorBlock(state::kBg), vectorBlock(state::kPbg),
                                               vectorBlock(state::kClockDrift, 1)};
  return kBlocks;
}

void DopplerModel::evaluate(const double* const* params, Eigen::VectorXd& residual,
                            std::vector<Eigen::MatrixXd>* jacobians) const {
  const Eigen::Vector3d v_n_b = vec3At(params[0]);
  const Eigen::Matrix3d R_n_b = quatAt(params[1]).toRotationMatrix();
  const Eigen::Vector3d w = gyro_ - vec3At(params[2]);
  const Eigen::Vector3d p_b_g = vec3At(params[3]);
  const double cdt_dot = params[4][0];
  const Eigen::Vector3d u = w.cross(p_b_g);  // antenna velocity relative to b, in b
  const Eigen::Vector3d v_ant_n = v_n_b + R_n_b * u;
  const long m = residualSize();
  residual.resize(m);
  if (jacobians) {
    jacobians->assign(5, Eigen::MatrixXd());
    for (size_t k = 0; k < 4; ++k) (*jacobians)[k].setZero(m, 3);
    (*jacobians)[4].setOnes(m, 1);
  }
  for (long a = 0; a < m; ++a) {
    const DopplerObservation& o = obs_[static_cast<size_t>(a)];
    const Eigen::RowVector3d e_n = (R_e_n_.transpose() * o.los_e).transpose();
    residual[a] = o.satellite_term - e_n * v_ant_n + cdt_dot - o.range_rate;
    if (!jacobians) continue;
    const Eigen::RowVector3d eR = e_n * R_n_b;
    (*jacobians)[0].row(a) = -e_n;
    (*jacobians)[1].row(a) = eR * skew(u);
    (*jacobians)[2].row(a) = -eR * skew(p_b_g);
    (*jacobians)[3].row(a) = -eR * skew(w);
  }
}

Eigen::MatrixXd DopplerModel::covariance() const {
  Eigen::VectorXd d(residualSize());
  for (size_t a = 0; a < obs_.size(); ++a) d[static_cast<long>(a)] = obs_[a].variance;
  return d.asDiagonal();
}

}  // namespace giocal
