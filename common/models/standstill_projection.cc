#include "common/models/standstill_projection.h"

#include <stdexcept>

namespace giocal {

StandstillProjection::StandstillProjection(std::shared_ptr<const MeasurementModel> model)
    : ProjectedModel(std::move(model), "+standstill") {
  const auto& b = blocks();
  for (size_t k = 0; k < b.size(); ++k) {
    for (const std::string& n : {block::kSv, block::kSw, block::kPbm, block::kQbm, block::kTdOdo}) {
      // Per-epoch blocks carry their epoch: "s_v@i".
      if (b[k].name == n || b[k].name.rfind(n + "@", 0) == 0) calibration_blocks_.push_back(k);
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
