#include "ekf/kalman_update.h"

#include <Eigen/Cholesky>

namespace giocal {

UpdateResult kalmanUpdate(Eigen::MatrixXd& P, const MeasurementRows& rows, double chi2_gate) {
  UpdateResult out;
  const Eigen::MatrixXd PHt = P * rows.H.transpose();
  const Eigen::MatrixXd S = rows.H * PHt + rows.R;
  const Eigen::LLT<Eigen::MatrixXd> llt(S);
  if (llt.info() != Eigen::Success) return out;
  const Eigen::VectorXd innovation = -rows.residual;
  out.nis = innovation.dot(llt.solve(innovation));
  if (!(out.nis <= chi2_gate)) return out;
  const Eigen::MatrixXd K = llt.solve(PHt.transpose()).transpose();
  out.dx = K * innovation;
  const Eigen::MatrixXd IKH = Eigen::MatrixXd::Identity(P.rows(), P.cols()) - K * rows.H;
  P = IKH * P * IKH.transpose() + K * rows.R * K.transpose();
  P = 0.5 * (P + P.transpose());
  out.accepted = true;
  return out;
}

}  // namespace giocal
