#include "common/models/nhc_model.h"

#include "common/models/block_values.h"
#include "common/odometer/vehicle_velocity.h"

namespace giocal {

const std::vector<StateBlock>& NhcModel::blocks() const {
  static const std::vector<StateBlock> kBlocks{vectorBlock(state::kV), rotationBlock(state::kQ),
                                               vectorBlock(state::kBg), vectorBlock(state::kPbm),
                                               rotationBlock(state::kQbm)};
  return kBlocks;
}

void NhcModel::evaluate(const double* const* params, Eigen::VectorXd& residual,
                        std::vector<Eigen::MatrixXd>* jacobians) const {
  const VehicleVelocity vv =
      vehicleVelocity(vec3At(params[0]), quatAt(params[1]), gyro_, vec3At(params[2]),
                      vec3At(params[3]), quatAt(params[4]));
  // Rows x (lateral) and z (vertical) of the vehicle velocity.
  Eigen::Matrix<double, 2, 3> S;
  S << 1, 0, 0, 0, 0, 1;
  residual = S * vv.v_m;
  if (jacobians) {
    // Into the caller's matrices: no allocation when it hands back the same ones.
    std::vector<Eigen::MatrixXd>& J = *jacobians;
    J.resize(5);
    const Eigen::Matrix3d* d[5] = {&vv.dv_dv_n, &vv.dv_dq_n_b, &vv.dv_dbg, &vv.dv_dp_b_m,
                                   &vv.dv_dq_b_m};
    for (size_t k = 0; k < 5; ++k) J[k] = S * *d[k];
  }
}

Eigen::MatrixXd NhcModel::covariance() const {
  Eigen::MatrixXd R;
  covarianceInto(R);
  return R;
}

void NhcModel::covarianceInto(Eigen::MatrixXd& R) const {
  R = Eigen::Matrix2d::Identity() * sigma_ * sigma_;
}

}  // namespace giocal
