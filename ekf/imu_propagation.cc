#include "ekf/imu_propagation.h"

#include <array>
#include <optional>

#include "common/math/rotation.h"

namespace giocal {

NavState navState(const StateRegistry& s) {
  NavState x;
  x.p_n_b = s.value(state::kP);
  x.q_n_b = quatFromWxyz(s.value(state::kQ).data());
  x.v_n_b = s.value(state::kV);
  x.b_a = s.value(state::kBa);
  x.b_g = s.value(state::kBg);
  return x;
}

void setNavState(StateRegistry& s, const NavState& x) {
  s.value(state::kP) = x.p_n_b;
  quatToWxyz(x.q_n_b, s.value(state::kQ).data());
  s.value(state::kV) = x.v_n_b;
  s.value(state::kBa) = x.b_a;
  s.value(state::kBg) = x.b_g;
}

std::optional<GyroTilt> gyroTilt(const StateRegistry& s) {
  if (!s.has(state::kGyroTilt)) return std::nullopt;
  return GyroTilt(s.value(state::kGyroTilt));
}

void propagateImu(StateRegistry& s, const ImuPreintegration& pre) {
  PropagationScratch scratch;
  propagateImu(s, pre, scratch);
}

void propagateImu(StateRegistry& s, const ImuPreintegration& pre, PropagationScratch& scratch) {
  const NavState xi = navState(s);
  const std::optional<GyroTilt> tilt = gyroTilt(s);
  const NavState xj = pre.predict(xi, tilt);
  const ImuResidual r = pre.evaluate(xi, xj, tilt);
  // Residual Jacobians in the variable order p, q, v, b_a, b_g.
  Eigen::Matrix<double, 15, 15> Ji;
  Ji << r.J_p_i, r.J_q_i, r.J_v_i, r.J_ba_i, r.J_bg_i;
  const Eigen::Matrix<double, 15, 15> Jj_inv = endStateJacobianInverse(r);
  const Eigen::Matrix<double, 15, 15> Q = Jj_inv * pre.covariance() * Jj_inv.transpose();

  // Only the navigation rows of Phi differ from identity: P' = Phi P Phi^T touches the navigation
  // rows and columns only, at O(15 n) instead of O(n^3). G: those rows over the navigation
  // states, then the gyro tilt's when it is estimated.
  std::array<int, 17> idx{};  // error-state index of each column of G (no allocation per call)
  int used = 0;
  for (const StateKey& key : {state::kP, state::kQ, state::kV, state::kBa, state::kBg}) {
    for (int k = 0; k < 3; ++k) idx[static_cast<size_t>(used++)] = s.offset(key) + k;
  }
  const int m = tilt ? 17 : 15;
  Eigen::MatrixXd& G = scratch.G;
  G.resize(15, m);
  G.leftCols<15>() = -Jj_inv * Ji;
  if (tilt) {
    G.rightCols<2>() = -Jj_inv * r.J_tilt;
    for (int k = 0; k < 2; ++k) idx[static_cast<size_t>(used++)] = s.offset(state::kGyroTilt) + k;
  }
  Eigen::MatrixXd& P = s.covariance();
  const int n = s.dim();
  Eigen::MatrixXd& Pn = scratch.Pn;  // the rows of P that G reads
  Pn.resize(m, n);
  for (int a = 0; a < m; ++a) Pn.row(a) = P.row(idx[static_cast<size_t>(a)]);
  Eigen::MatrixXd& FPn = scratch.FPn;  // new navigation rows against the old state
  FPn.resize(15, n);
  // The biases are random walks: G's bias rows pick their own columns (ones and exact zeros),
  // so their rows of F P are P's as they were; only the nine moving rows need the product.
  FPn.topRows<9>().noalias() = G.topRows<9>() * Pn;
  FPn.bottomRows<6>() = Pn.middleRows<6>(9);
  Eigen::MatrixXd& FPnn = scratch.FPnn;
  FPnn.resize(15, m);
  for (int b = 0; b < m; ++b) FPnn.col(b) = FPn.col(idx[static_cast<size_t>(b)]);
  // Into the fixed-size result directly: `FPnn * G^T + Q` made a heap temporary per call.
  Eigen::Matrix<double, 15, 15> Pnn_new;
  Pnn_new.noalias() = FPnn * G.transpose();
  Pnn_new += Q;
  for (int a = 0; a < 15; ++a) {
    const int i = idx[static_cast<size_t>(a)];
    P.row(i) = FPn.row(a);
    P.col(i) = FPn.row(a).transpose();
  }
  for (int a = 0; a < 15; ++a)
    for (int b = 0; b < 15; ++b)
      P(idx[static_cast<size_t>(a)], idx[static_cast<size_t>(b)]) =
          0.5 * (Pnn_new(a, b) + Pnn_new(b, a));
  setNavState(s, xj);
}

}  // namespace giocal
