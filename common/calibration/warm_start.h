// Warm start: a calibration carried from an earlier drive of the same robot to the next, its
// covariance grown for the time between them (a random walk per parameter), so that a robot
// calibrates once and refines on every drive.
#pragma once

#include <map>
#include <string>

#include "common/io/dataset_description.h"

namespace giocal {

/// How fast each calibration parameter may drift between drives [per sqrt(day)].
struct WarmStartOptions {
  double s_v = 1e-3, s_w = 1e-3;  // tyre wear, load
  double p_b_m = 0.005;           // [m] a mount settling
  double rpy_deg = 0.05;          // [deg]
};

/// What identifies the robot a calibration belongs to: dataset.yaml's GNSS lever arm and sensor
/// noise, by name ("p_b_g.x", "imu.gyro_noise_density", ...).
std::map<std::string, double> robotFingerprint(const DatasetDescription& d);

/// The first key whose value differs between two fingerprints (the lever arm by more than 1 cm,
/// the rest beyond rounding), with both values, or "" when they match.
std::string robotMismatch(const std::map<std::string, double>& earlier,
                          const std::map<std::string, double>& now);

/// `earlier` (its mean and its 8x8 tangent covariance) as the prior of a drive `dt_s` seconds
/// later: the covariance's diagonal grown by each parameter's random walk over that time.
CalibrationPrior carriedPrior(const CalibrationPrior& earlier, double dt_s,
                              const WarmStartOptions& o);

}  // namespace giocal
