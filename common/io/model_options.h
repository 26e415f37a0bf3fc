// ModelOptions: the options of the shared measurement models (motion detection, constraint noise,
// out-of-plane noise of the odometer), with their defaults, loadable from YAML.
#pragma once

#include <string>

#include "common/motion/motion_detector.h"

namespace giocal {

class YamlFields;

struct ModelOptions {
  MotionDetectorOptions motion;
  double zupt_sigma = 0.01;  // zero-velocity noise [m/s]
  double nhc_sigma = 0.05;   // lateral/vertical vehicle speed noise [m/s]
  // The EKF applies NHC once per this interval, the samples' information in one update (sigma /
  // sqrt(samples)), as the factor graph does once per epoch: the same constraint at a fraction of
  // the covariance updates (0: at every odometer sample) [s].
  double nhc_interval_s = 0.1;
  double lateral_speed_density = 0.01;  // odometer slip and uneven ground [m/s/sqrt(Hz)]
  double tilt_rate_density = 0.005;     // roll/pitch rate of uneven ground [rad/s/sqrt(Hz)]
  double lever_arm_min_turn = 6.0;      // an odometer interval informs p_b_m only when the states
                                        // turned by more than this many gyro sigmas over it [sigma]
};

/// Reads the "models" section of a giocal YAML config; keys left out keep their defaults.
/// Throws DataError naming the file, line and problem.
ModelOptions readModelOptions(const std::string& path);
/// The same from a configuration already parsed (keys asked for are remembered, see
/// YamlFields::rejectUnknownKeys).
ModelOptions readModelOptions(const YamlFields& y);

}  // namespace giocal
