// SingleReceiverUpdate: one rover epoch without a base in the EKF: the time-differenced carrier
// phase against a clone of the pose at the previous epoch (screened against the displacement the
// filter predicts, then gated row by row), Doppler with the receiver clock drift, and the single
// point position with a loose weight; then the clone moves to this epoch. The rows' slow error
// is a first-order Gauss-Markov antenna velocity (state::kTdcpDrift) when
// SingleReceiverOptions::tdcp_drift_sigma is set, the single point positions' a Gauss-Markov
// offset (state::kSppBias) when spp_bias_sigma is.
#pragma once

#include "common/gnss/broadcast_orbits.h"
#include "common/gnss/spp.h"
#include "common/gnss/time_differenced_phase.h"
#include "ekf/calibration_filter.h"
#include "ekf/gnss_update.h"

namespace giocal {

class SingleReceiverUpdate {
 public:
  SingleReceiverUpdate(const BroadcastOrbits& orbits, const CalibrationOptions& options);
  /// Propagates `filter` to the rover epoch and updates it; `fixed` stays false (nothing is
  /// fixed without a base).
  GnssEpochReport process(CalibrationFilter& filter, const ObsEpoch& rover);
  const TdcpCounts& tdcpCounts() const { return builder_.totals(); }
  std::vector<SatId> takeNewlyBroken() { return builder_.takeNewlyBroken(); }

 private:
  /// The TDCP rows that pass, as one update; returns the rows used.
  int updateTdcp(CalibrationFilter& f, TdcpPair pair, GnssEpochReport& rep);
  bool updatePosition(CalibrationFilter& f, const SppSolution& spp);
  /// Adds the drift state or carries it to the pair's second epoch (its stationary covariance
  /// from the pair's sky); false where the sky fixes no drift (the rows then go without it).
  bool advanceDrift(CalibrationFilter& f, const TdcpPair& pair, const Eigen::Vector3d& ant_e);
  /// Adds the single point positions' bias state or carries it to the filter's time, its
  /// stationary covariance Q (n) from this solution's sky.
  void advanceSppBias(CalibrationFilter& f, const Eigen::Matrix3d& Q);

  const BroadcastOrbits& orbits_;
  CalibrationOptions options_;
  TdcpBuilder builder_;
  double t_last_ = NAN;
  double clone_t_ = NAN;     // when the clone kGnssP/kGnssQ was taken
  double drift_t_ = NAN;     // the time state::kTdcpDrift stands at
  double spp_bias_t_ = NAN;  // the time state::kSppBias stands at
};

}  // namespace giocal
