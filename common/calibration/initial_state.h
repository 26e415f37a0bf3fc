// findInitialState(): the first navigation state of a calibrator and its covariance. Roll, pitch
// and the gyro bias come from a static window (wheels still); the heading from the RTK
// displacement of the antenna compared with the displacement dead-reckoned from the odometer and
// gyro in a yaw-free frame through the prior extrinsic. The heading error is then tied to the
// prior's extrinsic yaw error, and the returned covariance says so.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include "common/calibration/calibration_inputs.h"
#include "common/calibration/calibration_options.h"
#include "common/geodesy/wgs84.h"
#include "common/gnss/broadcast_orbits.h"
#include "common/gnss/rtk.h"
#include "common/imu/nav_state.h"

namespace giocal {

struct InitialState {
  Eigen::Vector3d origin_e = Eigen::Vector3d::Zero();  // origin of n: the antenna at the anchor
  NavState x;                                          // at a GNSS epoch time x.t
  /// Covariance of the navigation error [p, theta, v, b_a, b_g] and its cross-covariance with the
  /// calibration tangent error [s_v, s_w, p_b_m, theta_b_m] (the heading is computed through the
  /// prior extrinsic, so their yaw errors are correlated).
  Eigen::Matrix<double, 15, 15> P_nav = Eigen::Matrix<double, 15, 15>::Zero();
  Eigen::Matrix<double, 15, 8> P_nav_calib = Eigen::Matrix<double, 15, 8>::Zero();
  double static_window_s = 0.0;  // length of the alignment window (0: aligned in motion)
  double heading_baseline_m = 0.0;
  double heading_sigma = 0.0;  // [rad], from the displacement alone
};

/// The antenna's RTK solutions kept between attempts of findInitialState() on growing data (the
/// online calibrator tries again as epochs arrive): the RTK filter is causal, so the solutions
/// of the epochs already solved from the same start epoch, with the same orbits, do not change.
struct InitialRtkCache {
  double start = NAN;      // time of the first epoch solved
  size_t ephemerides = 0;  // the orbits' size when the solutions were made
  std::unique_ptr<BroadcastOrbits> orbits;
  std::unique_ptr<RtkFilter> filter;
  std::vector<RtkSolution> solutions;  // of the epochs from `start` on, in order
};

/// Searches from time `t_from` on, with the calibration `prior` (normally dataset.yaml's). Empty
/// when the data never allow it (no GNSS solution, the robot never drives far enough); `why` then
/// says what was missing. `cache` (optional) carries RTK solutions from an earlier attempt.
std::optional<InitialState> findInitialState(const CalibrationInputs& in,
                                             const CalibrationOptions& options,
                                             const CalibrationPrior& prior, double t_from,
                                             std::string* why, InitialRtkCache* cache = nullptr);

/// The calibration prior's tangent covariance [s_v, s_w, p_b_m, theta_b_m] from dataset.yaml.
Eigen::Matrix<double, 8, 8> priorCalibrationCovariance(const CalibrationPrior& prior);

}  // namespace giocal
