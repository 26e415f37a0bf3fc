// Rover Doppler observations prepared for a velocity update: the observed range rate -lambda D,
// the line of sight and the satellite's own part of the predicted range rate (its velocity, clock
// drift and the Sagnac rate), so a model only adds the receiver's velocity and clock drift.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "common/gnss/broadcast_orbits.h"
#include "common/gnss/dd_epoch.h"
#include "common/gnss/observation.h"
#include "common/gnss/weighting.h"

namespace giocal {

struct DopplerObservation {
  SatId sat;
  Eigen::Vector3d los_e = Eigen::Vector3d::Zero();  // unit vector from the rover to the satellite
  double satellite_term = 0.0;                      // los . v_sat - c dts_dot + Sagnac rate [m/s]
  double range_rate = 0.0;                          // observed: -lambda D [m/s]
  double variance = 0.0;                            // [m^2/s^2]
  double el = 0.0;                                  // [rad]
};

struct DopplerOptions {
  ElevationNoise noise{0.3};  // the reference paper's 0.3 m/s at zenith
  double elevation_mask_deg = 15.0;
  std::vector<GnssSystem> systems = defaultGnssSystems();
};

/// One Doppler per satellite (its primary band), for satellites with an ephemeris, above the mask
/// and with finite code and Doppler. `rover_e`: the antenna's approximate ECEF position.
/// `known`: satellites already solved at `rover_e` (a DdEpoch's), used where band and code match.
std::vector<DopplerObservation> dopplerObservations(const ObsEpoch& epoch,
                                                    const BroadcastOrbits& orbits,
                                                    const Eigen::Vector3d& rover_e,
                                                    const DopplerOptions& options,
                                                    const std::vector<RoverSatellite>& known = {});

}  // namespace giocal
