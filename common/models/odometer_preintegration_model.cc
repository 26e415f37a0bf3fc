#include "common/models/odometer_preintegration_model.h"

#include "common/imu/gyro_mean.h"
#include "common/math/so3.h"
#include "common/math/whitening.h"
#include "common/models/block_values.h"

namespace giocal {

const std::vector<StateBlock>& OdometerPreintegrationModel::blocks() const {
  static const std::vector<StateBlock> kBlocks{vectorBlock(at(state::kP, Copy::kI)),
                                               rotationBlock(at(state::kQ, Copy::kI)),
                                               vectorBlock(at(state::kP, Copy::kJ)),
                                               rotationBlock(at(state::kQ, Copy::kJ)),
                                               vectorBlock(at(state::kSv, Copy::kI), 1),
                                               vectorBlock(at(state::kSw, Copy::kI), 1),
                                               vectorBlock(state::kPbm),
                                               rotationBlock(state::kQbm)};
  static const std::vector<StateBlock> kWithDelay = [] {
    std::vector<StateBlock> b = kBlocks;
    b.push_back(vectorBlock(state::kTdOdo, 1));
    return b;
  }();
  return rates_ ? kWithDelay : kBlocks;
}

Eigen::Vector3d poseRate(const std::vector<ImuSample>& imu, double t, const Eigen::Vector3d& b_g,
                         double gyro_noise_density) {
  return meanGyro(imu, t, kPoseRateHalfWindow, gyro_noise_density).rate - b_g;
}

bool OdometerPreintegrationModel::informsLeverArm(const Eigen::Quaterniond& q_i,
                                                  const Eigen::Quaterniond& q_j,
                                                  const Eigen::Quaterniond& q_b_m) const {
  const OdometerPreintegrationNoise& n = pre_->noise();
  const double tilt_sigma = n.gyro_noise_density * std::sqrt(pre_->dt());  // the gyro's, per axis
  // About the vertical a measured yaw rate narrows the states' turn as well.
  const double odo_var = pre_->covariance()(5, 5);
  const double yaw_sigma = rows_ == 6 && odo_var > 0.0 && tilt_sigma > 0.0
                               ? 1.0 / std::sqrt(1.0 / (tilt_sigma * tilt_sigma) + 1.0 / odo_var)
                               : tilt_sigma;
  const Eigen::Vector3d turn_b = logSO3((q_i.conjugate() * q_j).toRotationMatrix());
  return turnBeyondNoise(turn_b, q_b_m * Eigen::Vector3d::UnitZ(), yaw_sigma, tilt_sigma,
                         n.lever_arm_min_turn);
}

OdometerPreintegrationModel::Whitener OdometerPreintegrationModel::whitenerAt(double s_v,
                                                                              double s_w) const {
  const Whitener C = pre_->covarianceAt(s_v, s_w).topLeftCorner(rows_, rows_);
  return whitenerOf(C, [this] { return name(); });
}

OdometerPreintegrationNoise odometerPreintegrationNoise(const OdometerNoise& odometer,
                                                        double gyro_noise_density,
                                                        const ModelOptions& models) {
  OdometerPreintegrationNoise n;
  n.gyro_noise_density = gyro_noise_density;
  n.speed_sigma = odometer.speed_sigma;
  n.yaw_rate_sigma = odometer.yaw_rate_sigma;
  n.lateral_speed_density = models.lateral_speed_density;
  n.tilt_rate_density = models.tilt_rate_density;
  n.lever_arm_min_turn = models.lever_arm_min_turn;
  return n;
}

void OdometerPreintegrationModel::evaluate(const double* const* params, Eigen::VectorXd& residual,
                                           std::vector<Eigen::MatrixXd>* jacobians) const {
  // Written into the caller's residual and Jacobians, and fixed-size temporaries: a caller that
  // keeps them across updates (the EKF) allocates nothing here.
  OdometerCalibration c;
  c.s_v = params[4][0];
  // A speed-only odometer's heading came from the gyro, divided by 1 + s_w at the interval's
  // start: the integral is evaluated there, and nothing here depends on (or measures) s_w.
  c.s_w = rows_ == 6 ? params[5][0] : pre_->linSw();
  c.p_b_m = vec3At(params[6]);
  c.q_b_m = quatAt(params[7]);
  // Without the delay block the poses are the states'; with it, the IMU poses the late stamps
  // stand for.
  const double t_d = rates_ ? params[8][0] : 0.0;
  const PoseRates rates = rates_.value_or(PoseRates{});
  const Eigen::Matrix3d R_i = expSO3(-t_d * rates.w_b_i), R_j = expSO3(-t_d * rates.w_b_j);
  const OdometerResidual r = rates_ ? pre_->evaluate(vec3At(params[0]) - t_d * rates.v_n_i,
                                                     Eigen::Quaterniond(quatAt(params[1]) * R_i),
                                                     vec3At(params[2]) - t_d * rates.v_n_j,
                                                     Eigen::Quaterniond(quatAt(params[3]) * R_j), c)
                                    : pre_->evaluate(vec3At(params[0]), quatAt(params[1]),
                                                     vec3At(params[2]), quatAt(params[3]), c);
  const Whitener W = whitenerAt(c.s_v, c.s_w);
  const int n = rows_;
  const Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1> rr = r.r.head(n);
  residual.noalias() = W * rr;
  if (!jacobians) return;
  std::vector<Eigen::MatrixXd>& J = *jacobians;
  J.resize(rates_ ? 9 : 8);
  const auto whiten = [&](Eigen::MatrixXd& out, const auto& rows) {
    out.noalias() = W * rows.topRows(n);
  };
  whiten(J[0], r.J_p_i);
  whiten(J[1], r.J_q_i);
  whiten(J[2], r.J_p_j);
  whiten(J[3], r.J_q_j);
  whiten(J[4], r.J_s_v);
  whiten(J[5], r.J_s_w);
  whiten(J[6], r.J_p_b_m);
  whiten(J[7], r.J_q_b_m);
  if (rates_) {
    // q Exp(d) Exp(-a) = q Exp(-a) Exp(Exp(a) d): the shifted pose's Jacobian times Exp(a).
    whiten(J[1], Eigen::Matrix<double, 6, 3>(r.J_q_i * R_i.transpose()));
    whiten(J[3], Eigen::Matrix<double, 6, 3>(r.J_q_j * R_j.transpose()));
    const Eigen::Matrix<double, 6, 1> J_t_d = -(r.J_p_i * rates.v_n_i + r.J_q_i * rates.w_b_i +
                                                r.J_p_j * rates.v_n_j + r.J_q_j * rates.w_b_j);
    whiten(J[8], J_t_d);
  }
  if (!informsLeverArm(quatAt(params[1]), quatAt(params[3]), c.q_b_m)) J[6].setZero();
  // The whitening's own dependence on the scales (central differences: W is smooth and cheap).
  const double h = 1e-6;
  const Whitener dW_v = whitenerAt(c.s_v + h, c.s_w) - whitenerAt(c.s_v - h, c.s_w);
  J[4].noalias() += dW_v * rr / (2 * h);
  if (n == 6) {
    const Whitener dW_w = whitenerAt(c.s_v, c.s_w + h) - whitenerAt(c.s_v, c.s_w - h);
    J[5].noalias() += dW_w * rr / (2 * h);
  } else {
    J[5].setZero();  // evaluated at the interval's s_w, whatever the block holds
  }
}

void OdometerPreintegrationModel::covarianceInto(Eigen::MatrixXd& R) const {
  R.setIdentity(rows_, rows_);
}

}  // namespace giocal
