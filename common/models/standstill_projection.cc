#include "common/models/standstill_projection.h"

#include <stdexcept>

#include "common/models/block_values.h"

namespace giocal {

StandstillProjection::StandstillProjection(std::shared_ptr<const MeasurementModel> inner)
    : inner_(std::move(inner)) {
  const auto& b = inner_->blocks();
  for (size_t k = 0; k < b.size(); ++k) {
    for (const std::string& n : {block::kSv, block::kSw, block::kPbm, block::kQbm}) {
      // Per-epoch blocks carry their epoch: "s_v@i".
      if (b[k].name == n || b[k].name.rfind(n + "@", 0) == 0) calibration_blocks_.push_back(k);
    }
  }
  if (calibration_blocks_.empty()) {
    throw std::invalid_argument(inner_->name() + " has no calibration blocks to project");
  }
}

void StandstillProjection::evaluate(const double* const* params, Eigen::VectorXd& residual,
                                    std::vector<Eigen::MatrixXd>* jacobians) const {
  inner_->evaluate(params, residual, jacobians);
  if (!jacobians) return;
  for (size_t k : calibration_blocks_) (*jacobians)[k].setZero();
}

}  // namespace giocal
