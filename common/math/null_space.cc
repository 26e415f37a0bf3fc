#include "common/math/null_space.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace giocal {

Eigen::VectorXd jacobiScale(const Eigen::MatrixXd& H) {
  return H.diagonal().unaryExpr([](double h) { return h > 0.0 ? 1.0 / std::sqrt(h) : 1.0; });
}

std::vector<int> unobservedIndices(const Eigen::MatrixXd& H, const std::vector<int>& idx,
                                   double share) {
  const Eigen::VectorXd d = jacobiScale(H);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(d.asDiagonal() * H * d.asDiagonal());
  const double tol = kNullEigenvalue * std::max(1.0, eig.eigenvalues().cwiseAbs().maxCoeff());
  std::vector<int> out;
  for (const int i : idx) {
    bool unobserved = !(H(i, i) > 0.0);
    for (Eigen::Index k = 0; k < H.rows() && !unobserved; ++k) {
      unobserved = eig.eigenvalues()[k] <= tol && std::abs(eig.eigenvectors()(i, k)) > share;
    }
    if (unobserved) out.push_back(i);
  }
  return out;
}

}  // namespace giocal
