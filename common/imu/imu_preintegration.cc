#include "common/imu/imu_preintegration.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace giocal {

namespace {

// One step's rotation terms from one set of coefficients: E = Exp(phi), Jr = Jr(phi),
// G1 = Jr(-phi) = Jr^T = int_0^1 Exp(s phi) ds and G2 = gamma2(phi) (four trigonometric
// evaluations per IMU sample were a tenth of the preintegration).
ImuPreintegration::StepRotation stepRotation(const Vec3& phi) {
  const So3Coefficients k = so3Coefficients(phi.norm());
  const Mat3 K = skew(phi), KK = K * K;
  const Mat3 B = k.b * K, C = k.c * KK;
  return {Mat3::Identity() + k.a * K + k.b * KK, Mat3::Identity() - B + C, Mat3::Identity() + B + C,
          0.5 * Mat3::Identity() + k.c * K + k.d * KK};
}

// The moving rows of the error-state transition, F = [A9 Ab], by their 3x3 blocks over
// [dp, dtheta, dv | dba, dbg]: A9 = [I A_pr I*dt; 0 A_rr 0; 0 A_vr I], Ab = [B_pa B_pg; 0 B_rg;
// B_va B_vg].
struct Transition {
  double dt = 0.0;
  Mat3 A_pr, A_rr, A_vr, B_pa, B_pg, B_rg, B_va, B_vg;

  /// F [X; Y] for the nine moving rows X and the six bias rows Y of a 15 x C matrix.
  template <int C>
  Eigen::Matrix<double, 9, C> apply(const Eigen::Matrix<double, 9, C>& X,
                                    const Eigen::Matrix<double, 6, C>& Y) const {
    const auto X_p = X.template topRows<3>(), X_r = X.template middleRows<3>(3);
    const auto X_v = X.template bottomRows<3>();
    const auto Y_a = Y.template topRows<3>(), Y_g = Y.template bottomRows<3>();
    Eigen::Matrix<double, 9, C> out;
    out.template topRows<3>() = X_p + dt * X_v + A_pr * X_r + B_pa * Y_a + B_pg * Y_g;
    out.template middleRows<3>(3) = A_rr * X_r + B_rg * Y_g;
    out.template bottomRows<3>() = X_v + A_vr * X_r + B_va * Y_a + B_vg * Y_g;
    return out;
  }

  /// F [X; Y] for X = (F P)^T's first nine rows and Y its last six, that is F P F^T's moving
  /// block, which is symmetric: its block upper triangle is computed and mirrored (a third fewer
  /// products, and exactly symmetric).
  Eigen::Matrix<double, 9, 9> applySymmetric(const Eigen::Matrix<double, 9, 9>& X,
                                             const Eigen::Matrix<double, 6, 9>& Y) const {
    Eigen::Matrix<double, 9, 9> out;
    const auto X_p = X.topRows<3>(), X_r = X.middleRows<3>(3), X_v = X.bottomRows<3>();
    const auto Y_a = Y.topRows<3>(), Y_g = Y.bottomRows<3>();
    out.topRows<3>() = X_p + dt * X_v + A_pr * X_r + B_pa * Y_a + B_pg * Y_g;
    out.block<3, 6>(3, 3) = A_rr * X_r.rightCols<6>() + B_rg * Y_g.rightCols<6>();
    out.block<3, 3>(6, 6) = X_v.rightCols<3>() + A_vr * X_r.rightCols<3>() +
                            B_va * Y_a.rightCols<3>() + B_vg * Y_g.rightCols<3>();
    out.block<6, 3>(3, 0) = out.block<3, 6>(0, 3).transpose();
    out.block<3, 3>(6, 3) = out.block<3, 3>(3, 6).transpose();
    return out;
  }
};

}  // namespace

using namespace imu_index;

ImuPreintegration::ImuPreintegration(const ImuNoise& noise, const Eigen::Vector3d& gravity_n,
                                     const Eigen::Vector3d& omega_ie_n, const Eigen::Vector3d& b_a,
                                     const Eigen::Vector3d& b_g,
                                     const std::optional<GyroTilt>& tilt)
    : noise_(noise),
      g_n_(gravity_n),
      w_ie_n_(omega_ie_n),
      b_a_lin_(b_a),
      b_g_lin_(b_g),
      tilt_lin_(tilt.value_or(GyroTilt::Zero())),
      with_tilt_(tilt.has_value()) {
  reset();
}

void ImuPreintegration::reset() {
  dt_sum_ = 0.0;
  dR_.setIdentity();
  dv_.setZero();
  dp_.setZero();
  dv_t_.setZero();
  dp_t_.setZero();
  cov_.setZero();
  J_bias_.setZero();
  J_tilt_.setZero();
  pending_.clear();
}

void ImuPreintegration::checkStep(const Step& s) {
  if (!(s.dt > 0.0) || !s.gyro.allFinite() || !s.acc.allFinite() ||
      !(s.extra_gyro_density >= 0.0) || !(s.extra_accel_density >= 0.0)) {
    throw std::invalid_argument("ImuPreintegration: step needs dt > 0 and finite samples");
  }
}

void ImuPreintegration::integrate(double dt, const Eigen::Vector3d& gyro,
                                  const Eigen::Vector3d& acc, double extra_gyro_density,
                                  double extra_accel_density) {
  const Step s{dt, gyro, acc, extra_gyro_density, extra_accel_density};
  checkStep(s);
  addStep(s);
  closeCovariance();
}

void ImuPreintegration::addChecked(const Step& s) {
  checkStep(s);
  addStep(s);
}

void ImuPreintegration::addStep(const Step& s) {
  const double dt = s.dt, dt2 = dt * dt;
  // Into the body frame halfway between the triads (GyroTilt): the rate turned by -d/2, the
  // specific force by +d/2, to first order (d is a fraction of a degree).
  const Vec3 d(tilt_lin_.x(), tilt_lin_.y(), 0.0);
  Vec3 w = s.gyro - b_g_lin_;
  Vec3 a = s.acc - b_a_lin_;
  w += 0.5 * w.cross(d);
  a -= 0.5 * a.cross(d);
  const Vec3 phi = w * dt;
  const StepRotation rot = stepRotation(phi);
  const Mat3 &E = rot.E, &G1 = rot.G1, &G2 = rot.G2;
  const Vec3 dv_step = dR_ * G1 * a * dt;
  const Vec3 dp_step = dR_ * G2 * a * dt2;

  PendingCovariance& c = pending_;
  if (c.samples++ == 0) {
    c.dR0 = dR_;
    c.w = w;
    c.a = a;
    c.rot = rot;
    c.eg2 = s.extra_gyro_density * s.extra_gyro_density;
    c.ea2 = s.extra_accel_density * s.extra_accel_density;
  }
  c.dt += dt;
  c.phi += phi;
  c.a_dt += a * dt;
  c.gyro_var_dt += s.extra_gyro_density * s.extra_gyro_density * dt;
  c.accel_var_dt += s.extra_accel_density * s.extra_accel_density * dt;

  // Time moments for the Earth-rotation terms (first order is enough: they scale with 7e-5 rad/s).
  const double tm = dt_sum_ + 0.5 * dt;
  dp_t_ += dv_t_ * dt + tm * dp_step;
  dv_t_ += tm * dv_step;

  dp_ += dv_ * dt + dp_step;
  dv_ += dv_step;
  dR_ = normalizeRotation(dR_ * E);
  dt_sum_ += dt;
  if (c.dt >= kCovarianceStep_s - 1e-9) closeCovariance();
}

void ImuPreintegration::closeCovariance() {
  PendingCovariance& c = pending_;
  if (c.samples == 0 || mean_only_) return;
  const double dt = c.dt, dt2 = dt * dt;
  // One sample keeps its own terms (bit for bit what a step per sample gives); several enter as
  // one step at their mean rate and specific force, their extra noise weighted by duration.
  Vec3 w = c.w, a = c.a;
  StepRotation rot = c.rot;
  if (c.samples > 1) {
    w = c.phi / dt;
    a = c.a_dt / dt;
    rot = stepRotation(c.phi);
  }
  const Mat3& R0 = c.dR0;

  // Error-state transition over [dp, dtheta, dv, dba, dbg]: the biases are carried unchanged, so
  // only the first nine rows move, F = [A9 Ab], applied by its 3x3 blocks (half of them 0 or I;
  // the blockwise form does 40 % fewer multiplications).
  Transition F;
  F.dt = dt;
  F.A_pr = -R0 * skew(rot.G2 * a) * dt2;
  F.A_rr = rot.E.transpose();
  F.A_vr = -R0 * skew(rot.G1 * a) * dt;
  F.B_pa = -R0 * rot.G2 * dt2;
  F.B_va = -R0 * rot.G1 * dt;
  F.B_pg = R0 * skew(a) * dt2 * dt / 6.0;  // dp by a gyro error
  F.B_rg = -rot.Jr * dt;
  F.B_vg = 0.5 * R0 * skew(a) * dt2;  // dv by a gyro error

  // cov <- F cov F^T + noise: M = F cov (9 x 15), then F M^T; the bias rows do not move.
  const Eigen::Matrix<double, 9, 15> M = F.apply<15>(cov_.topRows<9>(), cov_.bottomRows<6>());
  Eigen::Matrix<double, 9, 9> C11 =
      F.applySymmetric(M.leftCols<9>().transpose(), M.rightCols<6>().transpose());
  // Noise inputs: white gyro and accelerometer noise through the bias columns' blocks (a rate
  // error and a bias error enter alike), the bias random walks straight into the bias rows.
  const double sg = noise_.gyro_noise_density, sa = noise_.accel_noise_density;
  const double eg2 = c.samples > 1 ? c.gyro_var_dt / dt : c.eg2;
  const double ea2 = c.samples > 1 ? c.accel_var_dt / dt : c.ea2;
  const double q_g = (sg * sg + eg2) / dt, q_a = (sa * sa + ea2) / dt;
  Eigen::Matrix<double, 9, 3> B_g, B_a;
  B_g << F.B_pg, F.B_rg, F.B_vg;
  B_a << F.B_pa, Mat3::Zero(), F.B_va;
  C11.noalias() += q_g * B_g.lazyProduct(B_g.transpose());
  C11.noalias() += q_a * B_a.lazyProduct(B_a.transpose());
  cov_.topLeftCorner<9, 9>() = C11;
  cov_.topRightCorner<9, 6>() = M.rightCols<6>();
  cov_.bottomLeftCorner<6, 9>() = M.rightCols<6>().transpose();
  cov_.block<3, 3>(kBa, kBa).diagonal().array() +=
      noise_.accel_bias_random_walk * noise_.accel_bias_random_walk * dt;
  cov_.block<3, 3>(kBg, kBg).diagonal().array() +=
      noise_.gyro_bias_random_walk * noise_.gyro_bias_random_walk * dt;

  // Bias Jacobians follow the same transition; the bias columns are its input.
  J_bias_ = F.apply<6>(J_bias_, Eigen::Matrix<double, 6, 6>::Identity());
  if (with_tilt_) {
    // A tilt change acts as the bias changes -dw and -da it makes: dw = [w]x dd / 2,
    // da = -[a]x dd / 2, on d's x and y.
    Eigen::Matrix<double, 6, 2> tilt_as_bias;
    tilt_as_bias.topRows<3>() = 0.5 * skew(a).leftCols<2>();
    tilt_as_bias.bottomRows<3>() = -0.5 * skew(w).leftCols<2>();
    J_tilt_ = F.apply<2>(J_tilt_, tilt_as_bias);
  }
  c.clear();
}

void ImuPreintegration::integrateSamples(const std::vector<ImuSample>& samples, double t0,
                                         double t1, const ImuBridgeModel& bridge) {
  addSamples(samples, t0, t1, bridge);
  closeCovariance();
}

void ImuPreintegration::addSamples(const std::vector<ImuSample>& samples, double t0, double t1,
                                   const ImuBridgeModel& bridge) {
  if (!(t1 > t0)) throw std::invalid_argument("ImuPreintegration: needs t1 > t0");
  auto interp = [&](size_t k, double t) {
    const ImuSample& s0 = samples[k];
    const ImuSample& s1 = samples[k + 1];
    const double u = (t - s0.t) / (s1.t - s0.t);
    ImuSample s;
    s.t = t;
    s.gyro = (1.0 - u) * s0.gyro + u * s1.gyro;
    s.acc = (1.0 - u) * s0.acc + u * s1.acc;
    return s;
  };
  if (samples.size() < 2 || samples.front().t > t0 || samples.back().t < t1) {
    throw std::invalid_argument("ImuPreintegration: samples do not cover the interval");
  }
  // Start at the last sample at or before t0 (binary search: callers pass whole logs).
  const auto first = std::upper_bound(samples.begin(), samples.end(), t0,
                                      [](double t, const ImuSample& s) { return t < s.t; });
  for (size_t k = static_cast<size_t>(first - samples.begin()) - 1;
       k + 1 < samples.size() && samples[k].t < t1; ++k) {
    const double a = std::max(samples[k].t, t0), b = std::min(samples[k + 1].t, t1);
    if (b <= a) continue;
    const double span = samples[k + 1].t - samples[k].t;
    if (span <= bridge.min_interval_s) {
      const ImuSample sa = interp(k, a), sb = interp(k, b);
      addChecked({b - a, 0.5 * (sa.gyro + sb.gyro), 0.5 * (sa.acc + sb.acc), 0.0, 0.0});
      continue;
    }
    // A gap: short steps, so that the covariance accrues as over a continuous interval (one long
    // step leaves it singular), each with the noise of what the interpolation cannot know.
    const double grow = span * std::sqrt(span) / 4.0;
    const int n = static_cast<int>(std::ceil((b - a) / bridge.step_s));
    for (int i = 0; i < n; ++i) {
      const double ta = a + (b - a) * i / n, tb = a + (b - a) * (i + 1) / n;
      const ImuSample sa = interp(k, ta), sb = interp(k, tb);
      addChecked({tb - ta, 0.5 * (sa.gyro + sb.gyro), 0.5 * (sa.acc + sb.acc),
                  bridge.angular_accel * grow, bridge.jerk * grow});
    }
  }
}

Mat3 ImuPreintegration::correctedDeltaR(const Eigen::Vector3d& b_g,
                                        const std::optional<GyroTilt>& tilt) const {
  Vec3 phi = J_bias_.block<3, 3>(kR, 3) * (b_g - b_g_lin_);
  if (tilt) phi += J_tilt_.middleRows<3>(kR) * (*tilt - tilt_lin_);
  return dR_ * expSO3(phi);
}

Vec3 ImuPreintegration::corrected(int row, const Vec3& delta, const Eigen::Vector3d& b_a,
                                  const Eigen::Vector3d& b_g,
                                  const std::optional<GyroTilt>& tilt) const {
  Vec3 out = delta + J_bias_.block<3, 3>(row, 0) * (b_a - b_a_lin_) +
             J_bias_.block<3, 3>(row, 3) * (b_g - b_g_lin_);
  if (tilt) out += J_tilt_.middleRows<3>(row) * (*tilt - tilt_lin_);
  return out;
}

Vec3 ImuPreintegration::correctedDeltaV(const Eigen::Vector3d& b_a, const Eigen::Vector3d& b_g,
                                        const std::optional<GyroTilt>& tilt) const {
  return corrected(kV, dv_, b_a, b_g, tilt);
}

Vec3 ImuPreintegration::correctedDeltaP(const Eigen::Vector3d& b_a, const Eigen::Vector3d& b_g,
                                        const std::optional<GyroTilt>& tilt) const {
  return corrected(kP, dp_, b_a, b_g, tilt);
}

NavState ImuPreintegration::predict(const NavState& i, const std::optional<GyroTilt>& tilt) const {
  // Solves the residual of evaluate() for state j; the Coriolis terms depend on p_j - p_i, so
  // the position equation is solved first (I + T [w]x is inverted exactly).
  const double T = dt_sum_;
  const Mat3 R_i = i.q_n_b.toRotationMatrix();
  const Vec3 w_b = R_i.transpose() * w_ie_n_;
  NavState j;
  j.t = i.t + T;
  j.b_a = i.b_a;
  j.b_g = i.b_g;
  const Vec3 dP = correctedDeltaP(i.b_a, i.b_g, tilt) - skew(w_b) * dp_t_;
  const Vec3 dV = correctedDeltaV(i.b_a, i.b_g, tilt) - skew(w_b) * dv_t_;
  const Vec3 rhs_p = R_i * dP + i.v_n_b * T + 0.5 * g_n_ * T * T;
  const Vec3 dp_n = (Mat3::Identity() + T * skew(w_ie_n_)).inverse() * rhs_p;
  j.p_n_b = i.p_n_b + dp_n;
  j.v_n_b = i.v_n_b + g_n_ * T - 2.0 * skew(w_ie_n_) * dp_n + R_i * dV;
  const Mat3 R_j = expSO3(-w_ie_n_ * T) * R_i * correctedDeltaR(i.b_g, tilt);
  j.q_n_b = Eigen::Quaterniond(R_j).normalized();
  return j;
}

ImuResidual ImuPreintegration::evaluate(const NavState& i, const NavState& j,
                                        const std::optional<GyroTilt>& tilt) const {
  const double T = dt_sum_;
  const Mat3 R_i = i.q_n_b.toRotationMatrix();
  const Mat3 R_j = j.q_n_b.toRotationMatrix();
  const Mat3 Rt = R_i.transpose();
  const Mat3 W = skew(w_ie_n_);
  const Vec3 w_b = Rt * w_ie_n_;
  const Vec3 dbg = i.b_g - b_g_lin_;
  const Vec3 dpij = j.p_n_b - i.p_n_b;

  const Vec3 y_p = dpij - i.v_n_b * T - 0.5 * g_n_ * T * T + T * W * dpij;
  const Vec3 y_v = j.v_n_b - i.v_n_b - g_n_ * T + 2.0 * W * dpij;
  const Mat3 Ew = expSO3(w_ie_n_ * T);
  const Mat3 J_R_bg = J_bias_.block<3, 3>(kR, 3);
  const Eigen::Matrix<double, 3, 2> J_R_tilt = J_tilt_.middleRows<3>(kR);
  const Vec3 phi = J_R_bg * dbg + (tilt ? Vec3(J_R_tilt * (*tilt - tilt_lin_)) : Vec3::Zero());
  const Mat3 dR_hat = dR_ * expSO3(phi);
  const Vec3 r_R = logSO3(dR_hat.transpose() * Rt * Ew * R_j);
  const Mat3 JrInv = rightJacobianInvSO3(r_R);

  ImuResidual out;
  out.r.segment<3>(kP) = Rt * y_p + skew(w_b) * dp_t_ - correctedDeltaP(i.b_a, i.b_g, tilt);
  out.r.segment<3>(kR) = r_R;
  out.r.segment<3>(kV) = Rt * y_v + skew(w_b) * dv_t_ - correctedDeltaV(i.b_a, i.b_g, tilt);
  out.r.segment<3>(kBa) = j.b_a - i.b_a;
  out.r.segment<3>(kBg) = j.b_g - i.b_g;

  for (auto* J : {&out.J_p_i, &out.J_q_i, &out.J_v_i, &out.J_ba_i, &out.J_bg_i, &out.J_p_j,
                  &out.J_q_j, &out.J_v_j, &out.J_ba_j, &out.J_bg_j}) {
    J->setZero();
  }
  const Mat3 I = Mat3::Identity();
  out.J_p_i.block<3, 3>(kP, 0) = -Rt * (I + T * W);
  out.J_p_j.block<3, 3>(kP, 0) = Rt * (I + T * W);
  out.J_p_i.block<3, 3>(kV, 0) = -2.0 * Rt * W;
  out.J_p_j.block<3, 3>(kV, 0) = 2.0 * Rt * W;

  out.J_q_i.block<3, 3>(kP, 0) = skew(Rt * y_p) - skew(dp_t_) * skew(w_b);
  out.J_q_i.block<3, 3>(kV, 0) = skew(Rt * y_v) - skew(dv_t_) * skew(w_b);
  out.J_q_i.block<3, 3>(kR, 0) = -JrInv * R_j.transpose() * Ew.transpose() * R_i;
  out.J_q_j.block<3, 3>(kR, 0) = JrInv;

  out.J_v_i.block<3, 3>(kP, 0) = -Rt * T;
  out.J_v_i.block<3, 3>(kV, 0) = -Rt;
  out.J_v_j.block<3, 3>(kV, 0) = Rt;

  out.J_ba_i.block<3, 3>(kP, 0) = -J_bias_.block<3, 3>(kP, 0);
  out.J_ba_i.block<3, 3>(kV, 0) = -J_bias_.block<3, 3>(kV, 0);
  out.J_bg_i.block<3, 3>(kP, 0) = -J_bias_.block<3, 3>(kP, 3);
  out.J_bg_i.block<3, 3>(kV, 0) = -J_bias_.block<3, 3>(kV, 3);
  const Mat3 J_R_phi = -JrInv * expSO3(r_R).transpose() * rightJacobianSO3(phi);
  out.J_bg_i.block<3, 3>(kR, 0) = J_R_phi * J_R_bg;
  out.J_tilt.setZero();
  out.J_tilt.middleRows<3>(kP) = -J_tilt_.middleRows<3>(kP);
  out.J_tilt.middleRows<3>(kV) = -J_tilt_.middleRows<3>(kV);
  out.J_tilt.middleRows<3>(kR) = J_R_phi * J_R_tilt;

  out.J_ba_i.block<3, 3>(kBa, 0) = -I;
  out.J_ba_j.block<3, 3>(kBa, 0) = I;
  out.J_bg_i.block<3, 3>(kBg, 0) = -I;
  out.J_bg_j.block<3, 3>(kBg, 0) = I;
  return out;
}

Eigen::Matrix<double, 15, 15> endStateJacobianInverse(const ImuResidual& r) {
  using namespace imu_index;
  // J_j dx = dr row by row: dr_p = A dp, dr_theta = C dtheta, dr_v = B dp + D dv, and the biases
  // one to one; so dp = A^-1 dr_p, dtheta = C^-1 dr_theta, dv = D^-1 (dr_v - B A^-1 dr_p).
  const Mat3 A_inv = r.J_p_j.block<3, 3>(kP, 0).inverse();
  const Mat3 D_inv = r.J_v_j.block<3, 3>(kV, 0).inverse();
  Eigen::Matrix<double, 15, 15> inv = Eigen::Matrix<double, 15, 15>::Zero();
  inv.block<3, 3>(kP, kP) = A_inv;
  inv.block<3, 3>(kR, kR) = r.J_q_j.block<3, 3>(kR, 0).inverse();
  inv.block<3, 3>(kV, kP) = -D_inv * r.J_p_j.block<3, 3>(kV, 0) * A_inv;
  inv.block<3, 3>(kV, kV) = D_inv;
  inv.block<3, 3>(kBa, kBa) = Mat3::Identity();
  inv.block<3, 3>(kBg, kBg) = Mat3::Identity();
  return inv;
}

}  // namespace giocal
