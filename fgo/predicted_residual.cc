#include "fgo/predicted_residual.h"

#include <Eigen/Eigenvalues>

namespace giocal {

PredictedResidual predictedResidual(const SlidingWindow& window, const Factor& factor,
                                    double min_share) {
  std::vector<const double*> params;
  for (const StateKey& v : factor.vars) params.push_back(window.value(v).data());
  Eigen::VectorXd r;
  std::vector<Eigen::MatrixXd> J;
  factor.model->evaluate(params.data(), r, &J);
  std::vector<StateKey> names;
  std::vector<size_t> blocks;
  long cols = 0;
  for (size_t k = 0; k < factor.vars.size(); ++k) {
    if (window.isConstant(factor.vars[k])) continue;
    names.push_back(factor.vars[k]);
    blocks.push_back(k);
    cols += J[k].cols();
  }
  const Eigen::MatrixXd& S = *factor.sqrt_info;
  const Eigen::VectorXd e = S * r;
  Eigen::MatrixXd Jf(r.size(), cols);
  for (long c = 0, i = 0; i < static_cast<long>(blocks.size()); ++i) {
    Jf.middleCols(c, J[blocks[i]].cols()) = J[blocks[i]];
    c += J[blocks[i]].cols();
  }
  const Eigen::MatrixXd Jw = S * Jf;
  const Eigen::MatrixXd A = names.empty() ? Eigen::MatrixXd::Zero(r.size(), r.size())
                                          : window.covarianceAlong(names, Jw.transpose());
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(
      Eigen::MatrixXd::Identity(r.size(), r.size()) - 0.5 * (A + A.transpose()));
  PredictedResidual out;
  for (long i = 0; i < r.size(); ++i) {
    const double left = eig.eigenvalues()[i];
    if (left < min_share) continue;
    const double u = eig.eigenvectors().col(i).dot(e);
    out.chi2 += u * u / left;
    ++out.dof;
  }
  return out;
}

}  // namespace giocal
