// SkyView: what a receiver sees at one epoch, for reports: the satellites above the elevation mask
// with an ephemeris, and their position dilution of precision (PDOP).
#pragma once

#include <Eigen/Core>

#include "common/gnss/broadcast_orbits.h"
#include "common/gnss/observation.h"

namespace giocal {

struct SkyView {
  int satellites = 0;  // with a pseudo-range, an ephemeris and above the mask
  double pdop = NAN;   // NaN with fewer than four
};

/// PDOP of unit line-of-sight vectors (receiver to satellite, any frame) with one receiver clock:
/// sqrt(trace of the position block of (G^T G)^-1). NaN with fewer than four or a singular sky.
double positionDop(const std::vector<Eigen::Vector3d>& los);

/// The epoch's sky from a receiver at rx_e (ECEF, metres-level is enough).
SkyView skyView(const ObsEpoch& epoch, const BroadcastOrbits& orbits, const Eigen::Vector3d& rx_e,
                double elevation_mask_deg);

}  // namespace giocal
