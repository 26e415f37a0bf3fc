#include "fgo/model_cost_function.h"

#include <stdexcept>

#include "common/math/whitening.h"

namespace giocal {

ModelCostFunction::ModelCostFunction(std::shared_ptr<const MeasurementModel> model,
                                     std::shared_ptr<const Eigen::MatrixXd> sqrt_info)
    : model_(std::move(model)), sqrt_info_(std::move(sqrt_info)) {
  set_num_residuals(model_->residualSize());
  for (const auto& b : model_->blocks())
    mutable_parameter_block_sizes()->push_back(b.ambientSize());
  if (!sqrt_info_) {
    sqrt_info_ =
        std::make_shared<const Eigen::MatrixXd>(whitener(model_->covariance(), model_->name()));
  }
}

bool ModelCostFunction::Evaluate(const double* const* parameters, double* residuals,
                                 double** jacobians) const {
  Eigen::VectorXd r;
  std::vector<Eigen::MatrixXd> J;
  model_->evaluate(parameters, r, jacobians ? &J : nullptr);
  const int m = model_->residualSize();
  Eigen::Map<Eigen::VectorXd>(residuals, m) = *sqrt_info_ * r;
  if (!r.allFinite()) return false;
  if (!jacobians) return true;
  const auto& blocks = model_->blocks();
  for (size_t k = 0; k < blocks.size(); ++k) {
    if (!jacobians[k]) continue;
    const int ambient = blocks[k].ambientSize(), tangent = blocks[k].tangentSize();
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> out(
        jacobians[k], m, ambient);
    out.setZero();
    out.leftCols(tangent) = *sqrt_info_ * J[k];
  }
  return true;
}

}  // namespace giocal
