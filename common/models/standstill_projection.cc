#include "common/models/standstill_projection.h"

#include <stdexcept>

namespace giocal {

StandstillProjection::StandstillProjection(std::shared_ptr<const MeasurementModel> model)
    : ProjectedModel(std::move(model), "+standstill") {
  const auto& b = blocks();
  for (size_t k = 0; k < b.size(); ++k) {
    const Quantity q = b[k].key.what;
    if (q == Quantity::kSpeedScale || q == Quantity::kYawRateScale ||
        q == Quantity::kOdometerLever || q == Quantity::kOdometerMount ||
        q == Quantity::kOdometerDelay) {
      calibration_blocks_.push_back(k);
    }
  }
  if (calibration_blocks_.empty()) {
    throw std::invalid_argument(innerModel().name() + " has no calibration blocks to project");
  }
}

void StandstillProjection::project(const double* const* /*params*/,
                                   std::vector<Eigen::MatrixXd>& J) const {
  for (size_t k : calibration_blocks_) J[k].setZero();
}

}  // namespace giocal
