// The rover's Doppler in the EKF: one gated update of the velocity, attitude, gyro bias, lever
// arm and receiver clock drift, shared by the RTK scheme's epochs and the single receiver's.
#pragma once

#include <vector>

#include "common/gnss/broadcast_orbits.h"
#include "common/gnss/dd_epoch.h"
#include "ekf/calibration_filter.h"

namespace giocal {

/// The Doppler rows of one update: used, and left out by the gate.
struct DopplerRows {
  int used = 0, rejected = 0;
};

/// Updates `f` at the rover epoch (already propagated to it) with its Doppler: the clock drift
/// state starts from the median residual when absent or after `dt` > 30 s; the worst row beyond
/// the innovation gate goes until the rest pass (at least 4). `known`: satellites already solved
/// at ant_e.
DopplerRows updateDoppler(CalibrationFilter& f, const BroadcastOrbits& orbits,
                          const CalibrationOptions& options, const ObsEpoch& rover,
                          const Eigen::Vector3d& ant_e, const std::vector<RoverSatellite>& known,
                          double dt);

}  // namespace giocal
