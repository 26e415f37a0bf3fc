#include "common/models/planar_motion_projection.h"

#include <stdexcept>

#include "common/models/block_values.h"

namespace giocal {

PlanarMotionProjection::PlanarMotionProjection(std::shared_ptr<const MeasurementModel> model)
    : ProjectedModel(std::move(model), "+planar") {
  const auto& b = blocks();
  for (size_t k = 0; k < b.size(); ++k) {
    if (b[k].key == state::kPbm) p_block_ = static_cast<int>(k);
    if (b[k].key == state::kQbm) q_block_ = static_cast<int>(k);
  }
  if (p_block_ < 0 || q_block_ < 0) {
    throw std::invalid_argument(innerModel().name() + " has no p_b_m and q_b_m blocks to project");
  }
}

void PlanarMotionProjection::project(const double* const* params,
                                     std::vector<Eigen::MatrixXd>& J) const {
  const Eigen::Vector3d u = quatAt(params[q_block_]) * Eigen::Vector3d::UnitZ();
  Eigen::MatrixXd& J_p = J[static_cast<size_t>(p_block_)];
  const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - u * u.transpose();
  // Row by row through a fixed-size temporary: the whole product would be a heap temporary.
  for (Eigen::Index r = 0; r < J_p.rows(); ++r) J_p.row(r) = Eigen::RowVector3d(J_p.row(r) * P);
}

}  // namespace giocal
