#include "sim/trajectory.h"

#include <cmath>

#include "common/math/so3.h"

namespace giocal::sim {

Trajectory::Trajectory(MotionProfile profile, Terrain terrain, const Eigen::Vector3d& p0_n,
                       double initial_heading)
    : profile_(std::move(profile)), terrain_(terrain), p0_n_(p0_n) {
  const size_t n = static_cast<size_t>(std::ceil(profile_.duration() / node_dt_)) + 2;
  nodes_.reserve(n);
  nodes_.push_back({initial_heading, 0.0, p0_n.x(), p0_n.y()});
  for (size_t k = 1; k < n; ++k) {
    const double tk = static_cast<double>(k) * node_dt_;
    nodes_.push_back(integrate(nodes_.back(), tk - node_dt_, tk));
  }
}

void Trajectory::terrainSlope(double s, double& h, double& dh, double& d2h, double& d3h) const {
  const double k = 2.0 * M_PI / terrain_.wavelength, A = terrain_.amplitude;
  h = A * std::sin(k * s);
  dh = A * k * std::cos(k * s);
  d2h = -A * k * k * std::sin(k * s);
  d3h = -A * k * k * k * std::cos(k * s);
}

Trajectory::Node Trajectory::integrate(Node n, double t0, double t1) const {
  // RK4 on (psi, s, x, y); s is the horizontal distance travelled, advancing at the horizontal
  // speed V cos(theta) with theta = atan(h'(s)) the slope angle, so that dz/dt = h'(s) s' = V
  // sin(theta).
  auto deriv = [&](double t, const Node& x) {
    double v, v_dot, w, w_dot, h, dh, d2h, d3h;
    profile_.speed(t, v, v_dot);
    profile_.yawRate(t, w, w_dot);
    terrainSlope(x.s, h, dh, d2h, d3h);
    const double horizontal = v / std::sqrt(1.0 + dh * dh);
    // Heading psi rotates the forward axis (0, 1, 0) to (-sin psi, cos psi, 0).
    return Node{w, horizontal, -horizontal * std::sin(x.psi), horizontal * std::cos(x.psi)};
  };
  auto axpy = [](const Node& a, double h, const Node& d) {
    return Node{a.psi + h * d.psi, a.s + h * d.s, a.x + h * d.x, a.y + h * d.y};
  };
  const double max_step = 1e-3;
  double t = t0;
  while (t < t1 - 1e-15) {
    const double h = std::min(max_step, t1 - t);
    const Node k1 = deriv(t, n);
    const Node k2 = deriv(t + h / 2, axpy(n, h / 2, k1));
    const Node k3 = deriv(t + h / 2, axpy(n, h / 2, k2));
    const Node k4 = deriv(t + h, axpy(n, h, k3));
    n.psi += h / 6 * (k1.psi + 2 * k2.psi + 2 * k3.psi + k4.psi);
    n.s += h / 6 * (k1.s + 2 * k2.s + 2 * k3.s + k4.s);
    n.x += h / 6 * (k1.x + 2 * k2.x + 2 * k3.x + k4.x);
    n.y += h / 6 * (k1.y + 2 * k2.y + 2 * k3.y + k4.y);
    t += h;
  }
  return n;
}

VehicleKinematics Trajectory::at(double t) const {
  const double tc = std::clamp(t, 0.0, static_cast<double>(nodes_.size() - 1) * node_dt_);
  const size_t k = std::min(nodes_.size() - 1, static_cast<size_t>(tc / node_dt_));
  const Node n = integrate(nodes_[k], static_cast<double>(k) * node_dt_, tc);

  double v, v_dot, w, w_dot, h, dh, d2h, d3h;
  profile_.speed(tc, v, v_dot);
  profile_.yawRate(tc, w, w_dot);
  terrainSlope(n.s, h, dh, d2h, d3h);
  // Pitch theta = atan(h'(s)) and its time derivatives; s' = V cos(theta).
  const double q = 1.0 + dh * dh;
  const double th = std::atan(dh);
  const double dth_ds = d2h / q;
  const double d2th_ds2 = (d3h * q - 2.0 * dh * d2h * d2h) / (q * q);
  const double s_dot = v * std::cos(th);
  const double th_dot = dth_ds * s_dot;
  const double s_ddot = v_dot * std::cos(th) - v * std::sin(th) * th_dot;
  const double th_ddot = d2th_ds2 * s_dot * s_dot + dth_ds * s_ddot;
  PlanarMotion pm;
  pm.v = v;
  pm.v_dot = v_dot;
  // The profile's yaw rate W is the heading rate psi_dot (rotation about n's up axis).
  pm.psi = n.psi;
  pm.psi_dot = w;
  pm.psi_ddot = w_dot;
  pm.th = th;
  pm.th_dot = th_dot;
  pm.th_ddot = th_ddot;
  return planarKinematics(t, {n.x, n.y, p0_n_.z() + h}, pm);
}

VehicleKinematics planarKinematics(double t, const Eigen::Vector3d& p_n_m, const PlanarMotion& m) {
  const double v = m.v, v_dot = m.v_dot, psi = m.psi, psi_dot = m.psi_dot, psi_ddot = m.psi_ddot;
  const double th = m.th, th_dot = m.th_dot, th_ddot = m.th_ddot;
  VehicleKinematics out;
  out.t = t;
  out.speed = v;
  out.R_n_m = expSO3(Eigen::Vector3d(0, 0, psi)) * expSO3(Eigen::Vector3d(th, 0, 0));
  out.p_n_m = p_n_m;
  const double c = std::cos(th), s = std::sin(th), cp = std::cos(psi), sp = std::sin(psi);
  const double H = v * c;  // horizontal speed
  const double H_dot = v_dot * c - v * s * th_dot;
  out.v_n_m = {-H * sp, H * cp, v * s};
  out.a_n_m = {-H_dot * sp - H * cp * psi_dot, H_dot * cp - H * sp * psi_dot,
               v_dot * s + v * c * th_dot};
  // R_n_m = Rz(psi) Rx(theta): w_m = Rx(theta)^T (0, 0, psi_dot) + (theta_dot, 0, 0).
  out.w_m = {th_dot, psi_dot * s, psi_dot * c};
  out.alpha_m = {th_ddot, psi_ddot * s + psi_dot * th_dot * c, psi_ddot * c - psi_dot * th_dot * s};
  return out;
}

}  // namespace giocal::sim
