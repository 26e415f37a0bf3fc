#include "common/models/odometer_velocity_model.h"

#include "common/models/block_values.h"
#include "common/odometer/vehicle_velocity.h"

namespace giocal {

const std::vector<StateBlock>& OdometerVelocityModel::blocks() const {
  static const std::vector<StateBlock> kBlocks{
      vectorBlock(block::kV),     rotationBlock(block::kQ),   vectorBlock(block::kBg),
      vectorBlock(block::kSv, 1), vectorBlock(block::kSw, 1), vectorBlock(block::kPbm),
      rotationBlock(block::kQbm)};
  return kBlocks;
}

void OdometerVelocityModel::evaluate(const double* const* params, Eigen::VectorXd& residual,
                                     std::vector<Eigen::MatrixXd>* jacobians) const {
  const VehicleVelocity vv =
      vehicleVelocity(vec3At(params[0]), quatAt(params[1]), gyro_, vec3At(params[2]),
                      vec3At(params[5]), quatAt(params[6]));
  const double k_v = 1.0 / (1.0 + params[3][0]);
  const double k_w = 1.0 / (1.0 + params[4][0]);
  residual.resize(2);
  residual << vv.v_m.y() * k_v - sample_.v, vv.w_m.z() * k_w - sample_.w;
  if (!jacobians) return;
  const Eigen::RowVector3d ey(0, 1, 0), ez(0, 0, 1), zero(0, 0, 0);
  auto rows = [](const Eigen::RowVector3d& a, const Eigen::RowVector3d& b) {
    Eigen::Matrix<double, 2, 3> m;
    m << a, b;
    return m;
  };
  jacobians->assign(7, Eigen::MatrixXd());
  (*jacobians)[0] = rows(k_v * ey * vv.dv_dv_n, zero);
  (*jacobians)[1] = rows(k_v * ey * vv.dv_dq_n_b, zero);
  (*jacobians)[2] = rows(k_v * ey * vv.dv_dbg, k_w * ez * vv.dw_dbg);
  (*jacobians)[3] = Eigen::Vector2d(-vv.v_m.y() * k_v * k_v, 0.0);
  (*jacobians)[4] = Eigen::Vector2d(0.0, -vv.w_m.z() * k_w * k_w);
  (*jacobians)[5] = rows(k_v * ey * vv.dv_dp_b_m, zero);
  (*jacobians)[6] = rows(k_v * ey * vv.dv_dq_b_m, k_w * ez * vv.dw_dq_b_m);
}

Eigen::MatrixXd OdometerVelocityModel::covariance() const {
  return Eigen::Vector2d(speed_sigma_ * speed_sigma_, yaw_rate_sigma_ * yaw_rate_sigma_)
      .asDiagonal();
}

}  // namespace giocal
