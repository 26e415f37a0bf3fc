// The unit an IMU log's specific force is in (m/s^2, g or mg), told from its mean over the log.
#pragma once

#include <string>
#include <vector>

#include "common/imu/imu_sample.h"

namespace giocal {

struct AccelUnit {
  bool decided = false;    // false: the mean is gravity in none of the units
  std::string name;        // "m/s^2", "g" or "mg" (empty when not decided)
  double to_si = 1.0;      // multiply the log's values by this for m/s^2
  double mean_norm = 0.0;  // |mean specific force| in the log's own unit
};

/// Gravity (9.80665 m/s^2) within 10 % in one of the units: over a drive the vehicle's own
/// accelerations average out and gravity is left (a tilted IMU keeps its norm).
AccelUnit accelUnitOf(const std::vector<ImuSample>& imu);

/// The message `giocal check` and the importers give for an undecided unit, naming `where`.
std::string accelUnitProblem(const AccelUnit& u, const std::string& where);

}  // namespace giocal
