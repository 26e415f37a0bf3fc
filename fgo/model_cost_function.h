// ModelCostFunction: a MeasurementModel as a Ceres cost function, whitened by its covariance.
#pragma once

#include <ceres/cost_function.h>

#include <Eigen/Core>
#include <memory>

#include "common/models/measurement_model.h"

namespace giocal {

/// Parameter blocks follow model.blocks(): a Vector block of size n is n doubles, a Rotation block
/// 4 doubles [w, x, y, z] to be used with RightQuaternionManifold.
class ModelCostFunction : public ceres::CostFunction {
 public:
  /// `sqrt_info`: the model's whitener when already known (computed here otherwise).
  explicit ModelCostFunction(std::shared_ptr<const MeasurementModel> model,
                             std::shared_ptr<const Eigen::MatrixXd> sqrt_info = nullptr);
  bool Evaluate(const double* const* parameters, double* residuals,
                double** jacobians) const override;
  /// S with S^T S = covariance^-1: residuals are S (h(x) - z).
  const Eigen::MatrixXd& sqrtInformation() const { return *sqrt_info_; }

 private:
  std::shared_ptr<const MeasurementModel> model_;
  std::shared_ptr<const Eigen::MatrixXd> sqrt_info_;
};

}  // namespace giocal
