// The simulator's view of one satellite from one antenna: the exact light-time geometry from
// broadcast orbits and the simulator's own troposphere (not the estimators', so that a modelling
// error in one is not hidden by the same error in the other).
#pragma once

#include <Eigen/Core>

#include "common/gnss/broadcast_orbits.h"

namespace giocal::sim {

struct Geometry {
  double range, range_rate, clock, clock_drift, el, az;
  Eigen::Vector3d u;  // line of sight, receiver to satellite (ECEF)
};

/// Exact light-time solution for a signal received at true time t_rx by an antenna at p with
/// velocity v (ECEF): transmission time, Sagnac rotation by the flight time, the satellite clock
/// with the group delay of `band`. False when no ephemeris applies.
bool geometry(const BroadcastOrbits& orbits, const SatId& sat, double t_rx,
              const Eigen::Vector3d& p, const Eigen::Vector3d& v, char band, Geometry& g);

/// Simulator troposphere at height h [m] and elevation el [rad] with a zenith wet delay [m]:
/// exponential zenith delays and a continued-fraction-free mapping function.
double troposphere(double h, double el, double zwd);

}  // namespace giocal::sim
