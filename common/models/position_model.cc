#include "common/models/position_model.h"

#include "common/geodesy/wgs84.h"
#include "common/gnss/pos_reader.h"
#include "common/math/so3.h"
#include "common/models/block_values.h"

namespace giocal {

const std::vector<StateBlock>& PositionModel::blocks() const {
  static const std::vector<StateBlock> kBlocks{vectorBlock(state::kP), rotationBlock(state::kQ),
                                               vectorBlock(state::kPbg)};
  static const std::vector<StateBlock> kWithBias{vectorBlock(state::kP), rotationBlock(state::kQ),
                                                 vectorBlock(state::kPbg),
                                                 vectorBlock(state::kSppBias)};
  return with_bias_ ? kWithBias : kBlocks;
}

void PositionModel::evaluate(const double* const* params, Eigen::VectorXd& residual,
                             std::vector<Eigen::MatrixXd>* jacobians) const {
  const Vec3 p_n_b = vec3At(params[0]);
  const Mat3 R_n_b = quatAt(params[1]).toRotationMatrix();
  const Vec3 p_b_g = vec3At(params[2]);
  residual = p_n_b + R_n_b * p_b_g - z_;
  if (with_bias_) residual += vec3At(params[3]);
  // Right perturbation q Exp(theta): R (I + [theta]x) p_b_g = R p_b_g - R [p_b_g]x theta.
  if (jacobians) *jacobians = {Mat3::Identity(), -R_n_b * skew(p_b_g), R_n_b};
  if (jacobians && with_bias_) jacobians->push_back(Mat3::Identity());
}

PositionModel positionModelOf(const LocalFrame& frame, const PositionFix& fix,
                              const PositionWeighting& weighting) {
  const Geodetic g = geodeticFromEcef(fix.p_e);
  // ENU at the fix to n (the ENU frame at the origin): R_n_e R_e_enu.
  const Mat3 R = frame.R_e_n().transpose() * rotationEcefFromEnu(g.lat, g.lon);
  Mat3 cov_enu = fix.cov_enu * weighting.sigma_scale * weighting.sigma_scale;
  cov_enu.row(2) *= weighting.height_sigma_scale;
  cov_enu.col(2) *= weighting.height_sigma_scale;
  if (!weighting.use_height) {
    cov_enu.row(2).setZero();
    cov_enu.col(2).setZero();
    cov_enu(2, 2) = 1e6;
  }
  return PositionModel(frame.enuFromEcef(fix.p_e), R * cov_enu * R.transpose());
}

}  // namespace giocal
