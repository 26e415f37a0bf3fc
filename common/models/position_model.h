// PositionModel: a GNSS position solution of the antenna (the loosely coupled scheme), through the
// lever arm: residual = p_n_b + R_n_b p_b_g - p_n_antenna.
#pragma once

#include "common/models/measurement_model.h"

namespace giocal {

struct PositionFix;
class LocalFrame;

class PositionModel : public MeasurementModel {
 public:
  /// The antenna position in n and its covariance in n.
  PositionModel(const Eigen::Vector3d& p_n_antenna, const Eigen::Matrix3d& covariance_n)
      : z_(p_n_antenna), cov_(covariance_n) {}
  std::string name() const override { return "position"; }
  /// With a bias, the solution is the antenna plus state::kSppBias (an offset in n).
  PositionModel withBias() const {
    PositionModel m = *this;
    m.with_bias_ = true;
    return m;
  }
  const std::vector<StateBlock>& blocks() const override;  // p_n_b, q_n_b, p_b_g[, b_spp]
  int residualSize() const override { return 3; }
  void evaluate(const double* const* params, Eigen::VectorXd& residual,
                std::vector<Eigen::MatrixXd>* jacobians) const override;
  Eigen::MatrixXd covariance() const override { return cov_; }

 private:
  Eigen::Vector3d z_;
  Eigen::Matrix3d cov_;
  bool with_bias_ = false;
};

/// How far a position solution's own covariance is believed (the LC scheme's YAML keys
/// calibration.lc.*). Consumer receivers report sigmas their errors, slow and metres large, exceed.
struct PositionWeighting {
  double sigma_scale = 1.0;         // the solution's sigmas are multiplied by this
  bool use_height = true;           // false: the height is left out (its variance made 1e6 m^2), as
                                    // robot_localization's zero_altitude does for 2D robots
  double height_sigma_scale = 1.0;  // the height's sigma multiplied by this too (learned from the
                                    // drive, replay/measured_heights.h; not a YAML key)
  bool learn_heights = true;        // calibration.lc.learn_heights: check the heights before a run
};

/// The model of a position solution (ECEF, ENU covariance at the fix) in the local frame n.
PositionModel positionModelOf(const LocalFrame& frame, const PositionFix& fix,
                              const PositionWeighting& weighting = {});

}  // namespace giocal
