// ProjectedModel: a measurement model that is another model with only its Jacobians changed, the
// base of the observability-constrained wrappers (PlanarMotionProjection, StandstillProjection).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "common/models/measurement_model.h"

namespace giocal {

class ProjectedModel : public MeasurementModel {
 public:
  ProjectedModel(std::shared_ptr<const MeasurementModel> inner, std::string suffix)
      : inner_(std::move(inner)), suffix_(std::move(suffix)) {}
  std::string name() const override { return inner_->name() + suffix_; }
  const std::vector<StateBlock>& blocks() const override { return inner_->blocks(); }
  int residualSize() const override { return inner_->residualSize(); }
  /// The inner residual and Jacobians, then project() on the Jacobians.
  void evaluate(const double* const* params, Eigen::VectorXd& residual,
                std::vector<Eigen::MatrixXd>* jacobians) const final {
    inner_->evaluate(params, residual, jacobians);
    if (jacobians) project(params, *jacobians);
  }
  Eigen::MatrixXd covariance() const override { return inner_->covariance(); }
  void covarianceInto(Eigen::MatrixXd& R) const override { inner_->covarianceInto(R); }
  const MeasurementModel& innerModel() const { return *inner_; }

 protected:
  virtual void project(const double* const* params,
                       std::vector<Eigen::MatrixXd>& jacobians) const = 0;

 private:
  std::shared_ptr<const MeasurementModel> inner_;
  std::string suffix_;
};

}  // namespace giocal
