#include "common/odometer/odometer_preintegration.h"

#include <algorithm>
#include <stdexcept>

namespace giocal {

namespace {

Mat3 rotZ(double a) { return expSO3(Vec3(0.0, 0.0, a)); }

// Displacement, in the frame at the start of an arc, of unit speed for one time unit while turning
// by phi: (-(1 - cos phi)/phi, sin phi / phi, 0); and its derivative with respect to phi.
Vec3 arc(double phi) {
  if (std::abs(phi) < 1e-4) return {-phi / 2.0, 1.0 - phi * phi / 6.0, 0.0};
  return {-(1.0 - std::cos(phi)) / phi, std::sin(phi) / phi, 0.0};
}
Vec3 arcDerivative(double phi) {
  if (std::abs(phi) < 1e-4) return {-0.5 + phi * phi / 8.0, -phi / 3.0, 0.0};
  const double p2 = phi * phi;
  return {-(phi * std::sin(phi) - (1.0 - std::cos(phi))) / p2,
          (phi * std::cos(phi) - std::sin(phi)) / p2, 0.0};
}

}  // namespace

OdometerPreintegration::OdometerPreintegration(const OdometerPreintegrationNoise& noise, double s_v,
                                               double s_w)
    : noise_(noise), s_v_lin_(s_v), s_w_lin_(s_w) {}

Eigen::Matrix<double, 6, 6> OdometerPreintegration::covarianceAt(double s_v, double s_w) const {
  const double a_v = (1.0 + s_v) / (1.0 + s_v_lin_), a_w = (1.0 + s_w) / (1.0 + s_w_lin_);
  return cov_ + (a_v * a_v - 1.0) * cov_speed_ + (a_w * a_w - 1.0) * cov_yaw_rate_;
}

void OdometerPreintegration::integrate(double dt, double v, double w) {
  if (!(dt > 0.0) || !std::isfinite(v) || !std::isfinite(w)) {
    throw std::invalid_argument("OdometerPreintegration: step needs dt > 0 and finite samples");
  }
  const double k_w = 1.0 + s_w_lin_, k_v = 1.0 + s_v_lin_;
  const double theta = k_w * Theta_;
  const double phi = k_w * w * dt;
  const Mat3 Rz = rotZ(theta);
  const Vec3 step = Rz * arc(phi) * v * dt;  // per unit (1 + s_v)

  // Covariance of [dp_m, dtheta_m] (right perturbation of the m-frame rotation), with F_t and
  // G_t of the paper in m. Velocity of m in m: (0, k_v v, 0); rate: (0, 0, k_w w).
  const Vec3 v_m(0.0, k_v * v, 0.0);
  Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Identity();
  A.block<3, 3>(0, 3) = -Rz * skew(v_m) * dt;
  A.block<3, 3>(3, 3) = rotZ(phi).transpose();
  Eigen::Matrix<double, 6, 6> Q = Eigen::Matrix<double, 6, 6>::Zero();
  const double lat = noise_.lateral_speed_density * noise_.lateral_speed_density * dt;
  const double tilt = noise_.tilt_rate_density * noise_.tilt_rate_density * dt;
  // A sample's white noise holds over its interval (variance sigma^2 dt^2); the out-of-plane terms
  // are continuous densities (variance q^2 dt).
  const double var_v = k_v * k_v * noise_.speed_sigma * noise_.speed_sigma * dt * dt;
  const double var_w = k_w * k_w * noise_.yaw_rate_sigma * noise_.yaw_rate_sigma * dt * dt;
  Q.block<3, 3>(0, 0) = Rz * Eigen::Vector3d(lat, var_v, lat).asDiagonal() * Rz.transpose();
  Q.block<3, 3>(3, 3) = Eigen::Vector3d(tilt, tilt, var_w).asDiagonal();
  cov_ = A * cov_ * A.transpose() + Q;
  // The shares of the measured speed's and yaw rate's noise, which scale with (1 + s)^2.
  Eigen::Matrix<double, 6, 6> Q_v = Eigen::Matrix<double, 6, 6>::Zero();
  Q_v.block<3, 3>(0, 0) = var_v * Rz.col(1) * Rz.col(1).transpose();
  cov_speed_ = A * cov_speed_ * A.transpose() + Q_v;
  cov_yaw_rate_ = A * cov_yaw_rate_ * A.transpose();
  cov_yaw_rate_(5, 5) += var_w;

  // dP/ds_w: the step depends on s_w through theta = k_w Theta and phi = k_w w dt.
  dP_dsw_ +=
      (skew(Vec3::UnitZ()) * Rz * arc(phi) * Theta_ + Rz * arcDerivative(phi) * w * dt) * v * dt;
  P_ += step;
  Theta_ += w * dt;
  dt_sum_ += dt;
}

void OdometerPreintegration::integrateSamples(const std::vector<OdomSample>& samples, double t0,
                                              double t1) {
  if (!(t1 > t0)) throw std::invalid_argument("OdometerPreintegration: needs t1 > t0");
  if (samples.empty() || samples.front().t > t0) {
    throw std::invalid_argument("OdometerPreintegration: samples do not cover the interval");
  }
  // Samples are instantaneous readings: each piece between two samples integrates the mean of
  // the readings interpolated at its ends (exact for linear ramps, no half-sample lag); after
  // the last sample its reading holds.
  const auto first = std::upper_bound(samples.begin(), samples.end(), t0,
                                      [](double t, const OdomSample& s) { return t < s.t; });
  for (size_t k = static_cast<size_t>(first - samples.begin()) - 1;
       k < samples.size() && samples[k].t < t1; ++k) {
    const double a = std::max(samples[k].t, t0);
    if (k + 1 == samples.size()) {
      integrate(t1 - a, samples[k].v, samples[k].w);
      break;
    }
    const OdomSample& s0 = samples[k];
    const OdomSample& s1 = samples[k + 1];
    const double b = std::min(s1.t, t1);
    if (b <= a) continue;
    const auto at = [&](double t, double OdomSample::*f) {
      const double u = (t - s0.t) / (s1.t - s0.t);
      return (1.0 - u) * (s0.*f) + u * (s1.*f);
    };
    integrate(b - a, 0.5 * (at(a, &OdomSample::v) + at(b, &OdomSample::v)),
              0.5 * (at(a, &OdomSample::w) + at(b, &OdomSample::w)));
  }
}

double longestOdometerGap(const std::vector<OdomSample>& samples, double t0, double t1) {
  // Two readings bracketing part of [t0, t1] are as far apart as the gap integrateSamples
  // interpolates over, though only part of it may lie inside.
  double longest = 0.0, before = t0;
  for (const OdomSample& s : samples) {
    if (s.t > t0) longest = std::max(longest, s.t - before);
    if (s.t >= t1) return longest;
    before = s.t;
  }
  return std::max(longest, t1 - before);
}

bool turnBeyondNoise(const Vec3& turn_b, const Vec3& up_b, double yaw_sigma, double tilt_sigma,
                     double min_turn) {
  if (min_turn <= 0.0) return true;
  const double yaw = up_b.dot(turn_b);
  const Vec3 tilt = turn_b - yaw * up_b;
  const auto share = [](double x2, double sigma) {
    return sigma > 0.0 ? x2 / (sigma * sigma) : INFINITY;
  };
  return share(yaw * yaw, yaw_sigma) + share(tilt.squaredNorm(), tilt_sigma) > min_turn * min_turn;
}

double OdometerPreintegration::yaw(double s_w) const { return (1.0 + s_w) * Theta_; }

Vec3 OdometerPreintegration::deltaP_m(double s_v, double s_w) const {
  return (1.0 + s_v) * (P_ + dP_dsw_ * (s_w - s_w_lin_));
}

Mat3 OdometerPreintegration::deltaR_b(const OdometerCalibration& c) const {
  const Mat3 R_b_m = c.q_b_m.toRotationMatrix();
  return R_b_m * rotZ(yaw(c.s_w)) * R_b_m.transpose();
}

Vec3 OdometerPreintegration::deltaP_b(const OdometerCalibration& c) const {
  const Mat3 R_b_m = c.q_b_m.toRotationMatrix();
  return c.p_b_m + R_b_m * deltaP_m(c.s_v, c.s_w) - deltaR_b(c) * c.p_b_m;
}

OdometerResidual OdometerPreintegration::evaluate(const Vec3& p_i, const Eigen::Quaterniond& q_i,
                                                  const Vec3& p_j, const Eigen::Quaterniond& q_j,
                                                  const OdometerCalibration& c) const {
  const Mat3 R_i = q_i.toRotationMatrix(), R_j = q_j.toRotationMatrix();
  const Mat3 R_b_m = c.q_b_m.toRotationMatrix(), R_m_b = R_b_m.transpose();
  const Mat3 A = R_i.transpose() * R_j;                   // measured by the IMU states: R_bi_bj
  const Vec3 d_b = R_i.transpose() * (p_j - p_i);         // p_bi_bj
  const Vec3 z = d_b + (A - Mat3::Identity()) * c.p_b_m;  // R_b_m * (position of m_j in m_i)
  const Vec3 P_hat = P_ + dP_dsw_ * (c.s_w - s_w_lin_);
  const Mat3 B = R_m_b * A * R_b_m;  // R_mi_mj from the states
  const Mat3 dR_hat = rotZ(yaw(c.s_w));

  OdometerResidual out;
  out.r.head<3>() = R_m_b * z - (1.0 + c.s_v) * P_hat;
  const Vec3 r_th = logSO3(dR_hat.transpose() * B);
  out.r.tail<3>() = r_th;
  const Mat3 JrInv = rightJacobianInvSO3(r_th);

  out.J_p_i.topRows<3>() = -R_m_b * R_i.transpose();
  out.J_p_i.bottomRows<3>().setZero();
  out.J_p_j.topRows<3>() = R_m_b * R_i.transpose();
  out.J_p_j.bottomRows<3>().setZero();
  out.J_q_i.topRows<3>() = R_m_b * skew(d_b + A * c.p_b_m);
  out.J_q_i.bottomRows<3>() = -JrInv * B.transpose() * R_m_b;
  out.J_q_j.topRows<3>() = -R_m_b * A * skew(c.p_b_m);
  out.J_q_j.bottomRows<3>() = JrInv * R_m_b;
  out.J_p_b_m.topRows<3>() = R_m_b * (A - Mat3::Identity());
  out.J_p_b_m.bottomRows<3>().setZero();
  out.J_q_b_m.topRows<3>() = skew(R_m_b * z);
  out.J_q_b_m.bottomRows<3>() = JrInv * (Mat3::Identity() - B.transpose());
  out.J_s_v.head<3>() = -P_hat;
  out.J_s_v.tail<3>().setZero();
  out.J_s_w.head<3>() = -(1.0 + c.s_v) * dP_dsw_;
  out.J_s_w.tail<3>() = -JrInv * expSO3(r_th).transpose() * Vec3::UnitZ() * Theta_;
  return out;
}

}  // namespace giocal
