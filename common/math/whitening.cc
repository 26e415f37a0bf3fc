#include "common/math/whitening.h"

#include <Eigen/Cholesky>
#include <stdexcept>

namespace giocal {

Eigen::MatrixXd whitener(const Eigen::MatrixXd& C, const std::string& what) {
  const Eigen::LLT<Eigen::MatrixXd> llt(C);
  if (!C.allFinite() || llt.info() != Eigen::Success) {
    throw std::invalid_argument(what + ": covariance is not positive definite");
  }
  const Eigen::MatrixXd L = llt.matrixL();
  return L.triangularView<Eigen::Lower>().solve(Eigen::MatrixXd::Identity(C.rows(), C.cols()));
}

}  // namespace giocal
