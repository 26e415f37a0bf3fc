#include "common/gnss/fixed_phase_covariance.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "common/gnss/double_difference.h"

namespace giocal {

std::optional<Eigen::Matrix3d> fixedPhasePositionCovariance(const DdEpoch& epoch,
                                                            const Eigen::Vector3d& rover_e) {
  std::vector<DdObservation> rows;
  for (const DdObservation& o : epoch.obs) {
    if (o.phase) rows.push_back(o);
  }
  if (rows.size() < 3) return std::nullopt;
  Eigen::MatrixXd H(static_cast<long>(rows.size()), 3);
  for (size_t k = 0; k < rows.size(); ++k) {
    Eigen::RowVector3d J;
    ddPredict(rows[k], epoch.geometry, rover_e, 0.0, 0.0, &J);
    H.row(static_cast<long>(k)) = J;
  }
  // The rows share their reference satellite: correlated, as the estimators weigh them.
  const Eigen::MatrixXd R = ddCovariance(rows, epoch.undiff_variance);
  const Eigen::LLT<Eigen::MatrixXd> llt(R);
  if (llt.info() != Eigen::Success) return std::nullopt;
  const Eigen::MatrixXd W = llt.matrixL().solve(H);  // R^-1/2 H
  const Eigen::Matrix3d info = W.transpose() * W;
  // Satellites of one system in one plane (or all rows of one satellite pair) leave an axis open.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(info);
  if (!(eig.eigenvalues().minCoeff() > 1e-6 * eig.eigenvalues().maxCoeff())) return std::nullopt;
  return info.inverse();
}

}  // namespace giocal
