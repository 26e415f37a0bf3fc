#include "ekf/kalman_update.h"

#include <Eigen/Cholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>

namespace giocal {

namespace {

/// P H^T with H's zeros skipped: GNSS and odometer rows touch a few blocks of a long state.
Eigen::MatrixXd covarianceTimesHt(const Eigen::MatrixXd& P, const Eigen::SparseMatrix<double>& H) {
  return P * H.transpose();
}

}  // namespace

UpdateResult kalmanUpdate(Eigen::MatrixXd& P, const MeasurementRows& rows, double chi2_gate,
                          const std::vector<int>& held) {
  UpdateResult out;
  const Eigen::SparseMatrix<double> H = rows.H.sparseView();
  const Eigen::MatrixXd PHt = covarianceTimesHt(P, H);
  const Eigen::MatrixXd S = H * PHt + rows.R;
  const Eigen::LLT<Eigen::MatrixXd> llt(S);
  if (llt.info() != Eigen::Success) return out;
  const Eigen::VectorXd innovation = -rows.residual;
  out.nis = innovation.dot(llt.solve(innovation));
  if (!(out.nis <= chi2_gate)) return out;
  const Eigen::MatrixXd K0 = llt.solve(PHt.transpose()).transpose();
  Eigen::VectorXd gain_innovation = K0 * innovation;
  for (int i : held) gain_innovation[i] = 0.0;
  out.dx = gain_innovation;
  // Joseph form (I-KH) P (I-KH)^T + K R K^T with the optimal gain K0 = PH^T S^-1 and K = D K0,
  // D the mask of the states that are not held: with M = K0 S K0^T = K0 (PH^T)^T it expands to
  // P - D M - M D + D M D, which is P - M except on the held x held block, where it is P.
  Eigen::MatrixXd M = K0 * PHt.transpose();
  for (int i : held)
    for (int j : held) M(i, j) = 0.0;
  P -= M;
  P = 0.5 * (P + P.transpose());
  out.accepted = true;
  return out;
}

Eigen::VectorXd normalizedInnovations(const Eigen::MatrixXd& P, const MeasurementRows& rows) {
  const Eigen::MatrixXd PHt = covarianceTimesHt(P, rows.H.sparseView());
  Eigen::VectorXd z(rows.residual.size());
  for (long i = 0; i < z.size(); ++i) {
    const double s = rows.H.row(i).dot(PHt.col(i)) + rows.R(i, i);
    z[i] = std::abs(rows.residual[i]) / std::sqrt(std::max(s, 1e-300));
  }
  return z;
}

}  // namespace giocal
