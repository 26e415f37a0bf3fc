// TdcpModel: one receiver's time-differenced carrier phase predicted from the poses at the pair's
// two epochs through the GNSS lever arm (antenna p_e = origin + R_e_n (p_n_b + R_n_b p_b_g) at
// each), one row per satellite-minus-reference difference; the receiver clock's change cancels.
// The EKF gives it a clone of the pose at the first epoch, the factor graph two epochs' states.
// With a drift, the rows' slow error (satellite clock and orbit rates) enters as an antenna
// velocity v_tdcp (ENU) moving the second epoch's antenna by v_tdcp (t1 - t0).
#pragma once

#include <vector>

#include "common/geodesy/wgs84.h"
#include "common/gnss/time_differenced_phase.h"
#include "common/models/measurement_model.h"

namespace giocal {

class TdcpModel : public MeasurementModel {
 public:
  TdcpModel(const LocalFrame& frame, TdcpPair pair, bool with_drift = false);
  std::string name() const override { return "tdcp"; }
  /// p_n_b@i, q_n_b@i (the first epoch), p_n_b@j, q_n_b@j (the second), p_b_g; then v_tdcp
  /// with a drift.
  const std::vector<StateBlock>& blocks() const override;
  int residualSize() const override { return static_cast<int>(pair_.rows.size()); }
  /// residual = predicted - observed phase change difference [m]
  void evaluate(const double* const* params, Eigen::VectorXd& residual,
                std::vector<Eigen::MatrixXd>* jacobians) const override;
  Eigen::MatrixXd covariance() const override { return covariance_; }

 private:
  LocalFrame frame_;
  TdcpPair pair_;
  Eigen::MatrixXd covariance_;
  bool with_drift_ = false;
};

/// The stationary covariance (ENU, [m/s]^2) of the drift a pair's rows make when each
/// satellite's range rate is off by `sigma` [m/s], independently: the rows' weighted least-squares
/// velocity from those rates, at the antenna p_e (ECEF). NaN where the rows do not fix a velocity
/// (fewer than four satellites, or a degenerate sky).
Eigen::Matrix3d tdcpDriftCovariance(const LocalFrame& frame, const TdcpPair& pair,
                                    const Eigen::Vector3d& p_e, double sigma);

}  // namespace giocal
