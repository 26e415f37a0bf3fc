#include "common/imu/imu_preintegration.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace giocal {

namespace {

// Gamma2(phi) = int_0^1 int_0^u Exp(s phi) ds du, so that a constant rate and specific force over
// a step move position by dR * Gamma2 * a * dt^2.
Mat3 gamma2(const Vec3& phi) {
  const double th = phi.norm();
  const Mat3 K = skew(phi);
  if (th < 1e-4) return 0.5 * Mat3::Identity() + K / 6.0 + K * K / 24.0;
  const double t2 = th * th;
  return 0.5 * Mat3::Identity() + (th - std::sin(th)) / (t2 * th) * K +
         (t2 + 2.0 * std::cos(th) - 2.0) / (2.0 * t2 * t2) * K * K;
}

}  // namespace

using namespace imu_index;

ImuPreintegration::ImuPreintegration(const ImuNoise& noise, const Eigen::Vector3d& gravity_n,
                                     const Eigen::Vector3d& omega_ie_n, const Eigen::Vector3d& b_a,
                                     const Eigen::Vector3d& b_g)
    : noise_(noise), g_n_(gravity_n), w_ie_n_(omega_ie_n), b_a_lin_(b_a), b_g_lin_(b_g) {
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
}

void ImuPreintegration::integrate(double dt, const Eigen::Vector3d& gyro,
                                  const Eigen::Vector3d& acc, double extra_gyro_density,
                                  double extra_accel_density) {
  if (!(dt > 0.0) || !gyro.allFinite() || !acc.allFinite() || !(extra_gyro_density >= 0.0) ||
      !(extra_accel_density >= 0.0)) {
    throw std::invalid_argument("ImuPreintegration: step needs dt > 0 and finite samples");
  }
  steps_.push_back({dt, gyro, acc, extra_gyro_density, extra_accel_density});
  addStep(steps_.back());
}

void ImuPreintegration::addStep(const Step& s) {
  const double dt = s.dt, dt2 = dt * dt;
  const Vec3 w = s.gyro - b_g_lin_;
  const Vec3 a = s.acc - b_a_lin_;
  const Vec3 phi = w * dt;
  const Mat3 E = expSO3(phi);
  const Mat3 Jr = rightJacobianSO3(phi);
  const Mat3 G1 = rightJacobianSO3(-phi);  // int_0^1 Exp(s phi) ds
  const Mat3 G2 = gamma2(phi);
  const Vec3 dv_step = dR_ * G1 * a * dt;
  const Vec3 dp_step = dR_ * G2 * a * dt2;

  // Error-state transition over [dp, dtheta, dv, dba, dbg]: A = [A9 Ab; 0 I], the biases carried
  // unchanged, so only the first nine rows move. cov <- A cov A^T + B Q B^T is formed blockwise
  // (a third of the full 15x15 products' work; this runs for every IMU sample). Lazy products:
  // at these sizes Eigen's blocked GEMM packs more than it multiplies (callgrind: -31 %).
  Eigen::Matrix<double, 9, 9> A9 = Eigen::Matrix<double, 9, 9>::Identity();
  Eigen::Matrix<double, 9, 6> Ab = Eigen::Matrix<double, 9, 6>::Zero();
  const Mat3 Ga_bg_v = 0.5 * dR_ * skew(a) * dt2;       // dv by a gyro error
  const Mat3 Ga_bg_p = dR_ * skew(a) * dt2 * dt / 6.0;  // dp by a gyro error
  const Mat3 Ga_p = -dR_ * G2 * dt2, Ga_v = -dR_ * G1 * dt;
  A9.block<3, 3>(kP, kR) = -dR_ * skew(G2 * a) * dt2;
  A9.block<3, 3>(kP, kV) = Mat3::Identity() * dt;
  A9.block<3, 3>(kR, kR) = E.transpose();
  A9.block<3, 3>(kV, kR) = -dR_ * skew(G1 * a) * dt;
  Ab.block<3, 3>(kP, kBa - 9) = Ga_p;
  Ab.block<3, 3>(kP, kBg - 9) = Ga_bg_p;
  Ab.block<3, 3>(kR, kBg - 9) = -Jr * dt;
  Ab.block<3, 3>(kV, kBa - 9) = Ga_v;
  Ab.block<3, 3>(kV, kBg - 9) = Ga_bg_v;
  // Noise inputs: white gyro and accelerometer noise into the first nine rows, the bias random
  // walks straight into the bias rows.
  Eigen::Matrix<double, 9, 3> B_g, B_a;
  B_g << Ga_bg_p, -Jr * dt, Ga_bg_v;
  B_a << Ga_p, Mat3::Zero(), Ga_v;

  const double sg = noise_.gyro_noise_density, sa = noise_.accel_noise_density;
  const double eg = s.extra_gyro_density, ea = s.extra_accel_density;
  const double q_g = (sg * sg + eg * eg) / dt, q_a = (sa * sa + ea * ea) / dt;
  const Eigen::Matrix<double, 9, 9> C11 = cov_.topLeftCorner<9, 9>();
  const Eigen::Matrix<double, 9, 6> C12 = cov_.topRightCorner<9, 6>();
  const Eigen::Matrix<double, 6, 6> C22 = cov_.bottomRightCorner<6, 6>();
  Eigen::Matrix<double, 9, 9> T;
  T.noalias() = A9.lazyProduct(C11);
  T.noalias() += Ab.lazyProduct(C12.transpose());
  Eigen::Matrix<double, 9, 6> U;
  U.noalias() = A9.lazyProduct(C12);
  U.noalias() += Ab.lazyProduct(C22);
  Eigen::Matrix<double, 9, 9> C11_new;
  C11_new.noalias() = T.lazyProduct(A9.transpose());
  C11_new.noalias() += U.lazyProduct(Ab.transpose());
  C11_new.noalias() += q_g * B_g.lazyProduct(B_g.transpose());
  C11_new.noalias() += q_a * B_a.lazyProduct(B_a.transpose());
  cov_.topLeftCorner<9, 9>() = C11_new;
  cov_.topRightCorner<9, 6>() = U;
  cov_.bottomLeftCorner<6, 9>() = U.transpose();
  cov_.block<3, 3>(kBa, kBa).diagonal().array() +=
      noise_.accel_bias_random_walk * noise_.accel_bias_random_walk * dt;
  cov_.block<3, 3>(kBg, kBg).diagonal().array() +=
      noise_.gyro_bias_random_walk * noise_.gyro_bias_random_walk * dt;

  // Bias Jacobians follow the same transition; the bias columns are its input.
  const Eigen::Matrix<double, 9, 6> J_bias = A9.lazyProduct(J_bias_) + Ab;  // not in place
  J_bias_ = J_bias;

  // Time moments for the Earth-rotation terms (first order is enough: they scale with 7e-5 rad/s).
  const double tm = dt_sum_ + 0.5 * dt;
  dp_t_ += dv_t_ * dt + tm * dp_step;
  dv_t_ += tm * dv_step;

  dp_ += dv_ * dt + dp_step;
  dv_ += dv_step;
  dR_ = normalizeRotation(dR_ * E);
  dt_sum_ += dt;
}

void ImuPreintegration::integrateSamples(const std::vector<ImuSample>& samples, double t0,
                                         double t1, const ImuBridgeModel& bridge) {
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
      integrate(b - a, 0.5 * (sa.gyro + sb.gyro), 0.5 * (sa.acc + sb.acc));
      continue;
    }
    // A gap: short steps, so that the covariance accrues as over a continuous interval (one long
    // step leaves it singular), each with the noise of what the interpolation cannot know.
    const double grow = span * std::sqrt(span) / 4.0;
    const int n = static_cast<int>(std::ceil((b - a) / bridge.step_s));
    for (int i = 0; i < n; ++i) {
      const double ta = a + (b - a) * i / n, tb = a + (b - a) * (i + 1) / n;
      const ImuSample sa = interp(k, ta), sb = interp(k, tb);
      integrate(tb - ta, 0.5 * (sa.gyro + sb.gyro), 0.5 * (sa.acc + sb.acc),
                bridge.angular_accel * grow, bridge.jerk * grow);
    }
  }
}

void ImuPreintegration::repropagate(const Eigen::Vector3d& b_a, const Eigen::Vector3d& b_g) {
  b_a_lin_ = b_a;
  b_g_lin_ = b_g;
  reset();
  for (const Step& s : steps_) addStep(s);
}

Mat3 ImuPreintegration::correctedDeltaR(const Eigen::Vector3d& b_g) const {
  return dR_ * expSO3(J_bias_.block<3, 3>(kR, 3) * (b_g - b_g_lin_));
}

Vec3 ImuPreintegration::correctedDeltaV(const Eigen::Vector3d& b_a,
                                        const Eigen::Vector3d& b_g) const {
  return dv_ + J_bias_.block<3, 3>(kV, 0) * (b_a - b_a_lin_) +
         J_bias_.block<3, 3>(kV, 3) * (b_g - b_g_lin_);
}

Vec3 ImuPreintegration::correctedDeltaP(const Eigen::Vector3d& b_a,
                                        const Eigen::Vector3d& b_g) const {
  return dp_ + J_bias_.block<3, 3>(kP, 0) * (b_a - b_a_lin_) +
         J_bias_.block<3, 3>(kP, 3) * (b_g - b_g_lin_);
}

NavState ImuPreintegration::predict(const NavState& i) const {
  // Solves the residual of evaluate() for state j; the Coriolis terms depend on p_j - p_i, so
  // the position equation is solved first (I + T [w]x is inverted exactly).
  const double T = dt_sum_;
  const Mat3 R_i = i.q_n_b.toRotationMatrix();
  const Vec3 w_b = R_i.transpose() * w_ie_n_;
  NavState j;
  j.t = i.t + T;
  j.b_a = i.b_a;
  j.b_g = i.b_g;
  const Vec3 dP = correctedDeltaP(i.b_a, i.b_g) - skew(w_b) * dp_t_;
  const Vec3 dV = correctedDeltaV(i.b_a, i.b_g) - skew(w_b) * dv_t_;
  const Vec3 rhs_p = R_i * dP + i.v_n_b * T + 0.5 * g_n_ * T * T;
  const Vec3 dp_n = (Mat3::Identity() + T * skew(w_ie_n_)).inverse() * rhs_p;
  j.p_n_b = i.p_n_b + dp_n;
  j.v_n_b = i.v_n_b + g_n_ * T - 2.0 * skew(w_ie_n_) * dp_n + R_i * dV;
  const Mat3 R_j = expSO3(-w_ie_n_ * T) * R_i * correctedDeltaR(i.b_g);
  j.q_n_b = Eigen::Quaterniond(R_j).normalized();
  return j;
}

ImuResidual ImuPreintegration::evaluate(const NavState& i, const NavState& j) const {
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
  const Mat3 dR_hat = dR_ * expSO3(J_R_bg * dbg);
  const Vec3 r_R = logSO3(dR_hat.transpose() * Rt * Ew * R_j);
  const Mat3 JrInv = rightJacobianInvSO3(r_R);

  ImuResidual out;
  out.r.segment<3>(kP) = Rt * y_p + skew(w_b) * dp_t_ - correctedDeltaP(i.b_a, i.b_g);
  out.r.segment<3>(kR) = r_R;
  out.r.segment<3>(kV) = Rt * y_v + skew(w_b) * dv_t_ - correctedDeltaV(i.b_a, i.b_g);
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
  out.J_bg_i.block<3, 3>(kR, 0) =
      -JrInv * expSO3(r_R).transpose() * rightJacobianSO3(J_R_bg * dbg) * J_R_bg;

  out.J_ba_i.block<3, 3>(kBa, 0) = -I;
  out.J_ba_j.block<3, 3>(kBa, 0) = I;
  out.J_bg_i.block<3, 3>(kBg, 0) = -I;
  out.J_bg_j.block<3, 3>(kBg, 0) = I;
  return out;
}

}  // namespace giocal
