#include "common/imu/static_alignment.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/math/rotation.h"

namespace giocal {

StaticAlignment alignStatic(const std::vector<ImuSample>& window, double yaw,
                            const Eigen::Vector3d& omega_ie_n, double gyro_noise_density,
                            double accel_noise_density) {
  if (window.size() < 2) throw std::invalid_argument("static alignment needs at least two samples");
  Eigen::Vector3d f = Eigen::Vector3d::Zero(), w = Eigen::Vector3d::Zero();
  for (const ImuSample& s : window) {
    f += s.acc;
    w += s.gyro;
  }
  const double n = static_cast<double>(window.size());
  f /= n;
  w /= n;
  StaticAlignment a;
  // At rest the specific force is the reaction to gravity: f_b = R_n_b^T (0, 0, g), whose
  // direction is (-sin pitch, sin roll cos pitch, cos roll cos pitch) for R = Rz Ry Rx.
  a.roll = std::atan2(f.y(), f.z());
  a.pitch = std::atan2(-f.x(), std::hypot(f.y(), f.z()));
  const Mat3 R_n_b = rotationFromRpy(Vec3(a.roll, a.pitch, yaw));
  a.q_n_b = Eigen::Quaterniond(R_n_b).normalized();
  a.b_g = w - R_n_b.transpose() * omega_ie_n;
  const double T = window.back().t - window.front().t;
  const double span = std::max(T, 1e-3);
  a.sd_b_g = Eigen::Vector3d::Constant(gyro_noise_density / std::sqrt(span));
  a.sd_tilt = accel_noise_density / std::sqrt(span) / std::max(f.norm(), 1e-6);
  return a;
}

StaticAlignment withGyroBiasPrior(StaticAlignment a, double prior_sigma) {
  if (!(prior_sigma > 0.0)) return a;
  const double w_prior = 1.0 / (prior_sigma * prior_sigma);
  for (int i = 0; i < 3; ++i) {
    const double w_static = 1.0 / std::max(a.sd_b_g[i] * a.sd_b_g[i], 1e-20);
    a.b_g[i] *= w_static / (w_static + w_prior);
    a.sd_b_g[i] = 1.0 / std::sqrt(w_static + w_prior);
  }
  return a;
}

}  // namespace giocal
