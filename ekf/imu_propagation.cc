#include "ekf/imu_propagation.h"

#include <Eigen/LU>

#include "common/math/rotation.h"

namespace giocal {

NavState navState(const StateRegistry& s) {
  NavState x;
  x.p_n_b = s.value(nav_var::kP);
  x.q_n_b = quatFromWxyz(s.value(nav_var::kQ).data());
  x.v_n_b = s.value(nav_var::kV);
  x.b_a = s.value(nav_var::kBa);
  x.b_g = s.value(nav_var::kBg);
  return x;
}

void setNavState(StateRegistry& s, const NavState& x) {
  s.value(nav_var::kP) = x.p_n_b;
  quatToWxyz(x.q_n_b, s.value(nav_var::kQ).data());
  s.value(nav_var::kV) = x.v_n_b;
  s.value(nav_var::kBa) = x.b_a;
  s.value(nav_var::kBg) = x.b_g;
}

void propagateImu(StateRegistry& s, const ImuPreintegration& pre) {
  const NavState xi = navState(s);
  const NavState xj = pre.predict(xi);
  const ImuResidual r = pre.evaluate(xi, xj);
  // Residual Jacobians in the variable order p, q, v, b_a, b_g.
  Eigen::Matrix<double, 15, 15> Ji, Jj;
  Ji << r.J_p_i, r.J_q_i, r.J_v_i, r.J_ba_i, r.J_bg_i;
  Jj << r.J_p_j, r.J_q_j, r.J_v_j, r.J_ba_j, r.J_bg_j;
  const Eigen::Matrix<double, 15, 15> Jj_inv = Jj.inverse();
  const Eigen::Matrix<double, 15, 15> F = -Jj_inv * Ji;
  const Eigen::Matrix<double, 15, 15> Q = Jj_inv * pre.covariance() * Jj_inv.transpose();

  const int idx[5] = {s.offset(nav_var::kP), s.offset(nav_var::kQ), s.offset(nav_var::kV),
                      s.offset(nav_var::kBa), s.offset(nav_var::kBg)};
  const int n = s.dim();
  // Phi = identity except on the navigation rows; applied as P' = Phi P Phi^T + Q_nav.
  Eigen::MatrixXd Fn = Eigen::MatrixXd::Zero(15, n);  // new navigation errors from all errors
  for (int a = 0; a < 5; ++a)
    for (int b = 0; b < 5; ++b) Fn.block(3 * a, idx[b], 3, 3) = F.block<3, 3>(3 * a, 3 * b);
  Eigen::MatrixXd& P = s.covariance();
  const Eigen::MatrixXd FnP = Fn * P;                      // 15 x n
  const Eigen::MatrixXd FnPFt = FnP * Fn.transpose() + Q;  // 15 x 15
  for (int a = 0; a < 5; ++a) {
    for (int c = 0; c < n; ++c) {
      bool nav_col = false;
      for (int b = 0; b < 5; ++b) nav_col |= c >= idx[b] && c < idx[b] + 3;
      if (nav_col) continue;
      P.block(idx[a], c, 3, 1) = FnP.block(3 * a, c, 3, 1);
      P.block(c, idx[a], 1, 3) = FnP.block(3 * a, c, 3, 1).transpose();
    }
    for (int b = 0; b < 5; ++b) P.block(idx[a], idx[b], 3, 3) = FnPFt.block<3, 3>(3 * a, 3 * b);
  }
  setNavState(s, xj);
}

}  // namespace giocal
