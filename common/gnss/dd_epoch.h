// DdEpochBuilder: forms one epoch's double differences from rover and base observations: the
// satellites as each receiver saw them, single differences per band, cycle-slip flags, reference
// satellites (kept while high enough), and the code-based start value of every SD ambiguity.
// The RTK filter, the EKF and the factor graph all form their GNSS rows with it.
#pragma once

#include <map>
#include <utility>
#include <vector>

#include "common/gnss/broadcast_orbits.h"
#include "common/gnss/cycle_slip.h"
#include "common/gnss/double_difference.h"
#include "common/gnss/observation.h"
#include "common/gnss/weighting.h"

namespace giocal {

/// GPS, Galileo, BeiDou and QZSS: the systems giocal uses by default (GLONASS's FDMA phases do
/// not double-difference to integers). A function, not a brace list in each options struct:
/// GCC 12 warned about such lists in the structs' inlined constructors.
std::vector<GnssSystem> defaultGnssSystems();

struct DdOptions {
  double elevation_mask_deg = 15.0;
  int frequencies = 2;  // 1, 2 or 3 (see ddBands)
  std::vector<GnssSystem> systems = defaultGnssSystems();
  ElevationNoise code{0.3};
  ElevationNoise phase{0.003};
  double keep_reference_elevation_deg = 30.0;
  CycleSlipOptions slips;
};

/// One SD ambiguity seen this epoch [cycles], with whether its phase slipped (or is new).
struct SdAmbiguity {
  SatId sat;
  char band = '1';
  double code_value = 0.0;  // (SD phase - SD code) / lambda: the start value after a slip
  double lambda = 0.0;
  bool slipped = false;
};

/// Variance [cycles^2] of an SD ambiguity started (or restarted after a slip) from code: 10 m
/// covers code noise and multipath. The prior of every estimator's ambiguity states.
inline double ambiguityStartVariance(double lambda) { return (10.0 / lambda) * (10.0 / lambda); }

/// A satellite as the rover saw it: from the pseudo-range `code` on `band`, at the rover
/// position the epoch was built for (the Doppler rows reuse it instead of solving the orbit again).
struct RoverSatellite {
  SatId sat;
  char band = '1';
  double code = 0.0;
  SatelliteAtReception at;
};

struct DdEpoch {
  std::vector<SdGeometry> geometry;
  std::vector<RoverSatellite> rover_satellites;  // every one the orbits gave, in the rover's order
  std::vector<DdObservation> obs;                // phase and code rows
  std::vector<std::pair<double, double>>
      undiff_variance;  // per geometry: {code, phase}, rover+base
  std::vector<SdAmbiguity> ambiguities;
};

/// Bands used per system, in order: 1 frequency L1/E1/B1I; 2 adds L2/E5b/B2I; 3 adds L5/E5a/B3I
/// (each where the satellite and both receivers track it).
std::vector<char> ddBands(GnssSystem sys, int frequencies);

class DdEpochBuilder {
 public:
  DdEpochBuilder(const BroadcastOrbits& orbits, const Eigen::Vector3d& base_e,
                 const DdOptions& options);
  /// `rover_e`: the rover antenna's approximate ECEF position (for elevations and Sagnac).
  DdEpoch build(const ObsEpoch& rover, const ObsEpoch& base, const Eigen::Vector3d& rover_e);

 private:
  const BroadcastOrbits& orbits_;
  Eigen::Vector3d base_e_;
  DdOptions options_;
  CycleSlipDetector rover_slips_, base_slips_;
  std::map<std::pair<GnssSystem, char>, SatId> refs_;
};

}  // namespace giocal
