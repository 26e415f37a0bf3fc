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
  const Eigen::VectorXd s_innovation = llt.solve(innovation);
  out.nis = innovation.dot(s_innovation);
  if (!(out.nis <= chi2_gate)) return out;
  Eigen::VectorXd gain_innovation = PHt * s_innovation;  // K0 v, K0 = P H^T S^-1 never formed
  for (int i : held) gain_innovation[i] = 0.0;
  out.dx = gain_innovation;
  // Joseph form (I-KH) P (I-KH)^T + K R K^T with the optimal gain K0 = PH^T S^-1 and K = D K0,
  // D the mask of the states that are not held: with M = K0 S K0^T = K0 (PH^T)^T it expands to
  // P - D M - M D + D M D, which is P - M except on the held x held block, where it is P.
  // M = W^T W with W = L^-1 (PH^T)^T (S = L L^T): one triangular solve and a symmetric rank-m
  // update of P's lower triangle, half the work of forming K0 and K0 (PH^T)^T.
  const Eigen::MatrixXd W = llt.matrixL().solve(PHt.transpose());
  Eigen::MatrixXd P_held(held.size(), held.size());
  for (size_t a = 0; a < held.size(); ++a)
    for (size_t b = 0; b < held.size(); ++b) P_held(a, b) = P(held[a], held[b]);
  P.selfadjointView<Eigen::Lower>().rankUpdate(W.transpose(), -1.0);
  P.triangularView<Eigen::StrictlyUpper>() = P.transpose();
  for (size_t a = 0; a < held.size(); ++a)
    for (size_t b = 0; b < held.size(); ++b) P(held[a], held[b]) = P_held(a, b);
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
