#include "ekf/kalman_update.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

namespace giocal {

UpdateResult kalmanUpdate(Eigen::MatrixXd& P, const MeasurementRows& rows, double chi2_gate,
                          const std::vector<int>& held) {
  UpdateResult out;
  const Eigen::MatrixXd PHt = P * rows.H.transpose();
  const Eigen::MatrixXd S = rows.H * PHt + rows.R;
  const Eigen::LLT<Eigen::MatrixXd> llt(S);
  if (llt.info() != Eigen::Success) return out;
  const Eigen::VectorXd innovation = -rows.residual;
  out.nis = innovation.dot(llt.solve(innovation));
  if (!(out.nis <= chi2_gate)) return out;
  Eigen::MatrixXd K = llt.solve(PHt.transpose()).transpose();
  for (int i : held) K.row(i).setZero();
  out.dx = K * innovation;
  // Joseph form, valid for any gain K, expanded to O(n^2 m):
  // (I-KH) P (I-KH)^T + K R K^T = P - K (PH^T)^T - (PH^T) K^T + K S K^T.
  const Eigen::MatrixXd KS = K * S;
  const Eigen::MatrixXd KPHt = K * PHt.transpose();
  P.noalias() -= KPHt;
  P.noalias() -= KPHt.transpose();
  P.noalias() += KS * K.transpose();
  P = 0.5 * (P + P.transpose());
  out.accepted = true;
  return out;
}

Eigen::VectorXd normalizedInnovations(const Eigen::MatrixXd& P, const MeasurementRows& rows) {
  const Eigen::MatrixXd HP = rows.H * P;
  Eigen::VectorXd z(rows.residual.size());
  for (long i = 0; i < z.size(); ++i) {
    const double s = HP.row(i).dot(rows.H.row(i)) + rows.R(i, i);
    z[i] = std::abs(rows.residual[i]) / std::sqrt(std::max(s, 1e-300));
  }
  return z;
}

}  // namespace giocal
