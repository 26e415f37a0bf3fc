// whitener: the square-root information S (S^T S = C^-1) that turns a residual of covariance C
// into one of identity covariance; shared by every place that whitens a model.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <stdexcept>
#include <string>

namespace giocal {

/// S = L^-1 with C = L L^T. Throws std::invalid_argument naming `what` if C is not positive
/// definite or not finite.
Eigen::MatrixXd whitener(const Eigen::MatrixXd& C, const std::string& what);

/// The same in C's own type (fixed or bounded sizes stay off the heap); `what()` names the model
/// and is called only to say what failed.
template <typename Matrix, typename What>
Matrix whitenerOf(const Matrix& C, const What& what) {
  const Eigen::LLT<Matrix> llt(C);
  if (!C.allFinite() || llt.info() != Eigen::Success) {
    throw std::invalid_argument(what() + ": covariance is not positive definite");
  }
  Matrix S = Matrix::Identity(C.rows(), C.cols());
  llt.matrixL().solveInPlace(S);
  return S;
}

}  // namespace giocal
