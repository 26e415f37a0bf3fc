// SingleReceiverUpdate: one rover epoch without a base in the EKF: the time-differenced carrier
// phase against a clone of the pose at the previous epoch (screened against the displacement the
// filter predicts, then gated row by row), Doppler with the receiver clock drift, and the single
// point position with a loose weight; then the clone moves to this epoch.
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

  const BroadcastOrbits& orbits_;
  CalibrationOptions options_;
  TdcpBuilder builder_;
  double t_last_ = NAN;
  double clone_t_ = NAN;  // when the clone kGnssP/kGnssQ was taken
};

}  // namespace giocal
