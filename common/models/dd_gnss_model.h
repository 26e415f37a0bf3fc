// DdGnssModel: one epoch's double-differenced code and phase predicted from the IMU state through
// the GNSS lever arm (antenna p_e = origin + R_e_n (p_n_b + R_n_b p_b_g)) and the
// single-differenced ambiguities; the same rows serve the EKF update and the factor graph's GNSS
// factor.
#pragma once

#include <vector>

#include "common/geodesy/wgs84.h"
#include "common/gnss/double_difference.h"
#include "common/models/measurement_model.h"

namespace giocal {

class DdGnssModel : public MeasurementModel {
 public:
  /// `undiff_variance[i]` is the undifferenced variance (rover plus base) of geometry i's code and
  /// phase: {code, phase} [m^2]. Phase rows get one ambiguity block per satellite and band,
  /// keyed ambiguityKey(sat, band) (version 0), in cycles.
  DdGnssModel(const LocalFrame& frame, std::vector<SdGeometry> geometry,
              std::vector<DdObservation> observations,
              std::vector<std::pair<double, double>> undiff_variance);

  std::string name() const override { return "dd_gnss"; }
  /// p_n_b, q_n_b, p_b_g, then the ambiguities.
  const std::vector<StateBlock>& blocks() const override { return blocks_; }
  int residualSize() const override { return static_cast<int>(obs_.size()); }
  void evaluate(const double* const* params, Eigen::VectorXd& residual,
                std::vector<Eigen::MatrixXd>* jacobians) const override;
  Eigen::MatrixXd covariance() const override { return covariance_; }
  /// Into R's storage: no temporary of the epoch's m x m covariance.
  void covarianceInto(Eigen::MatrixXd& R) const override { R = covariance_; }

  /// Block index of the ambiguity of (sat, band), -1 if none.
  int ambiguityBlock(const SatId& sat, char band) const;

 private:
  LocalFrame frame_;
  std::vector<SdGeometry> geometry_;
  std::vector<DdObservation> obs_;
  std::vector<StateBlock> blocks_;
  std::vector<std::pair<SatId, char>> amb_keys_;  // block k + 3
  Eigen::MatrixXd covariance_;
};

}  // namespace giocal
