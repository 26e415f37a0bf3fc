// A static receiver's real observations moved along a synthesized antenna path: real GNSS noise,
// multipath, atmosphere and clocks on a moving antenna whose true path is known.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "common/gnss/broadcast_orbits.h"
#include "common/gnss/observation.h"
#include "sim/gnss_simulator.h"

namespace giocal::sim {

struct MovedRover {
  std::vector<ObsEpoch> epochs;  // those inside [t_begin, t_end]
  long signals = 0;              // signals moved
  long unsupported_signals = 0;  // left out: a system or band without a known carrier frequency
                                 // (GLONASS's FDMA, SBAS)
  long no_ephemeris = 0;         // satellite epochs left out: no ephemeris applies
  double max_move = 0.0;         // largest range change applied [m]
};

/// Each code, phase and Doppler of the receiver that stood at `static_e` (ECEF, surveyed) becomes
/// what the antenna on `path` receives at the same time tag (the path taken at the true reception
/// time, the tag less the receiver clock offset its codes show): the range and range rate of the
/// move (exact light time and Sagnac, sky_geometry.h) and the troposphere's change with height are
/// added, so that everything else stays the real receiver's. Left as it was: the ionosphere's and
/// multipath's change over the path (metres to hundreds of metres) and the phase wind-up of the
/// antenna turning with the vehicle, common to all satellites to first order (docs/design.md).
MovedRover moveStaticRover(const std::vector<ObsEpoch>& rover, const BroadcastOrbits& orbits,
                           const Eigen::Vector3d& static_e, const AntennaTruth& path,
                           double t_begin, double t_end);

}  // namespace giocal::sim
