#include "common/models/ambiguity_fix_model.h"

#include <algorithm>

namespace giocal {

AmbiguityFixModel::AmbiguityFixModel(std::vector<DdAmbiguityFix> fixes, double sigma_cycles)
    : fixes_(std::move(fixes)), sigma_(sigma_cycles) {
  auto blockOf = [&](const StateKey& key) {
    const auto it = std::find_if(blocks_.begin(), blocks_.end(),
                                 [&](const StateBlock& b) { return b.key == key; });
    if (it != blocks_.end()) return static_cast<int>(it - blocks_.begin());
    blocks_.push_back(vectorBlock(key, 1));
    return static_cast<int>(blocks_.size()) - 1;
  };
  for (const DdAmbiguityFix& f : fixes_)
    index_.push_back({blockOf(f.sat_block), blockOf(f.ref_block)});
}

void AmbiguityFixModel::evaluate(const double* const* params, Eigen::VectorXd& residual,
                                 std::vector<Eigen::MatrixXd>* jacobians) const {
  const long m = residualSize();
  residual.resize(m);
  if (jacobians) jacobians->assign(blocks_.size(), Eigen::MatrixXd::Zero(m, 1));
  for (long a = 0; a < m; ++a) {
    const auto [i, r] = index_[static_cast<size_t>(a)];
    residual[a] = params[i][0] - params[r][0] - fixes_[static_cast<size_t>(a)].value;
    if (jacobians) {
      (*jacobians)[static_cast<size_t>(i)](a, 0) = 1.0;
      (*jacobians)[static_cast<size_t>(r)](a, 0) = -1.0;
    }
  }
}

Eigen::MatrixXd AmbiguityFixModel::covariance() const {
  return Eigen::MatrixXd::Identity(residualSize(), residualSize()) * sigma_ * sigma_;
}

}  // namespace giocal
