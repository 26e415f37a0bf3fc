#include "sim/sensor_errors.h"

#include <cmath>

#include "common/math/rotation.h"
#include "common/math/so3.h"

namespace giocal::sim {

namespace {

constexpr double kMgal = 1e-5;  // m/s^2

Eigen::Vector3d gaussian3(std::mt19937_64& rng, double sd) {
  std::normal_distribution<double> n(0.0, 1.0);
  const double x = n(rng), y = n(rng), z = n(rng);
  return Eigen::Vector3d(x, y, z) * sd;
}

double gaussian(std::mt19937_64& rng, double sd) {
  std::normal_distribution<double> n(0.0, 1.0);
  return n(rng) * sd;
}

// (I + diag(s)) R: per-axis scale errors s after a misalignment rotation R, returned in `R_out`.
Eigen::Matrix3d scaleAndMisalignment(std::mt19937_64& rng, double scale_ppm, double mis_deg,
                                     Eigen::Matrix3d* R_out = nullptr) {
  const Eigen::Vector3d s = gaussian3(rng, scale_ppm * 1e-6);
  const Eigen::Vector3d m = gaussian3(rng, mis_deg * kDegToRad);
  if (R_out) *R_out = expSO3(m);
  return (Eigen::Matrix3d::Identity() + Eigen::Matrix3d(s.asDiagonal())) * expSO3(m);
}

double quantize(double x, double q) { return q > 0.0 ? std::round(x / q) * q : x; }

}  // namespace

ImuErrors::ImuErrors(const ImuErrorSpec& spec, std::mt19937_64& rng) : spec_(spec) {
  b_g_ = gaussian3(rng, spec.gyro_bias_deg_h * kDegToRad / 3600.0);
  b_a_ = gaussian3(rng, spec.accel_bias_mgal * kMgal);
  T_g_ = scaleAndMisalignment(rng, spec.scale_ppm, spec.misalignment_deg, &R_g_b_);
  T_a_ = scaleAndMisalignment(rng, spec.scale_ppm, spec.misalignment_deg, &R_a_b_);
}

ImuSample ImuErrors::measure(double t, const Eigen::Vector3d& gyro, const Eigen::Vector3d& acc,
                             double dt, std::mt19937_64& rng) {
  // White noise of density q sampled at interval dt has standard deviation q / sqrt(dt).
  const double arw = spec_.arw_deg_sqrt_h * kDegToRad / 60.0;  // rad/s/sqrt(Hz)
  const double vrw = spec_.vrw_m_s_sqrt_h / 60.0;              // m/s^2/sqrt(Hz)
  ImuSample s;
  s.t = t;
  s.gyro = T_g_ * gyro + b_g_ + gaussian3(rng, arw / std::sqrt(dt));
  s.acc = T_a_ * acc + b_a_ + gaussian3(rng, vrw / std::sqrt(dt));
  b_g_ +=
      gaussian3(rng, spec_.gyro_bias_rw_deg_h_sqrt_h * kDegToRad / 3600.0 / 60.0 * std::sqrt(dt));
  b_a_ += gaussian3(rng, spec_.accel_bias_rw_mgal_sqrt_s * kMgal * std::sqrt(dt));
  return s;
}

OdomSample OdometerErrors::measure(double t, double speed, double yaw_rate, double dt,
                                   std::mt19937_64& rng) {
  OdomSample s;
  s.t = t;
  double factor = 1.0;
  if (slip_left_ > 0.0) {
    slip_left_ -= dt;
    factor = spec_.slip_speed_factor;
  } else if (std::abs(speed) > 0.05 && spec_.slip_rate_per_min > 0.0) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    if (u(slip_rng_) < spec_.slip_rate_per_min / 60.0 * dt) {
      slip_left_ = spec_.slip_duration_s;
      ++slip_events_;
    }
  }
  s.v = quantize(factor * speed / (1.0 + s_v_) + gaussian(rng, spec_.speed_sigma),
                 spec_.speed_quantum);
  s.w = quantize(yaw_rate / (1.0 + s_w_) + gaussian(rng, spec_.yaw_rate_sigma_deg_s * kDegToRad),
                 spec_.yaw_rate_quantum_deg_s * kDegToRad);
  s_v_ += gaussian(rng, spec_.scale_drift_per_sqrt_s * std::sqrt(dt));
  s_w_ += gaussian(rng, spec_.scale_drift_per_sqrt_s * std::sqrt(dt));
  return s;
}

}  // namespace giocal::sim
