// Observability analysis: what a drive can calibrate, before calibrating. The EKF's covariance
// recursion is run along the drive's reference motion (truth.csv, linearized there, or a GNSS
// position solution), with the IMU and odometer logs and antenna positions as GNSS (with one
// receiver, options.single_receiver, its own TDCP, Doppler and single point positions): the
// expected sigma of each calibration state per time window and in total, the weakly observed
// states, the couplings between them and with the IMU heading, and advice on the motion that would
// help.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "common/calibration/calibration_inputs.h"
#include "common/calibration/calibration_options.h"
#include "common/calibration/reference_trajectory.h"

namespace giocal {

struct ObservabilityJob {
  CalibrationOptions options;
  /// The calibration the models are linearized at (the truth when known, else the guess); the
  /// prior's sigmas are the dataset's.
  OdometerCalibration linearize_at;
  /// The reference the navigation state is held on at every step (truth.csv); without one the
  /// filter runs on in.positions and its own estimate (the LC scheme's covariance).
  std::optional<ReferenceTrajectory> reference;
  double window_s = 30.0;
};

/// What the odometer shows of the motion in a window (uncalibrated: for advice, not accuracy).
struct DriveMotion {
  double duration_s = 0.0, distance_m = 0.0, turned_left_deg = 0.0, turned_right_deg = 0.0;
  double speed_change_m_s = 0.0;  // sum of |change of speed| (accelerating and braking)
  double still_s = 0.0;           // standing still
};

struct ObservabilityWindow {
  double t0 = 0.0, t1 = 0.0;  // seconds after the first rover epoch
  DriveMotion motion;
  Eigen::Matrix<double, 8, 1> sigma;  // at the window's end, calibration.csv order and units
  /// Information gained in the window per state: 1/sigma^2 at its end minus at its start,
  /// relative to the prior's 1/sigma^2.
  Eigen::Matrix<double, 8, 1> information;
};

struct ObservabilityReport {
  bool linearized_at_reference = false;
  Eigen::Matrix<double, 8, 1> prior_sigma, expected_sigma;  // calibration.csv order and units
  /// The component of p_b_m (calibration.csv index) along the vehicle's vertical: the one
  /// held in planar motion (p_b_m.z, unless the IMU is mounted on its side).
  int vertical_state = 4;
  /// The expected sigma of p_b_m along the vehicle's vertical were it estimated [m].
  double p_b_m_z_sigma_free = 0.0;
  bool p_b_m_z_observable = false;
  /// Only along a reference: linearized at its own estimate the filter finds spurious information
  /// along the vehicle's vertical (paper preset: 0.12 m against 0.17 m along the truth).
  bool p_b_m_z_assessed = false;
  std::vector<ObservabilityWindow> windows;
  DriveMotion total;
  std::vector<int> weak;               // calibration.csv indices, as the calibrators' warning
  std::vector<std::string> couplings;  // "yaw of q_b_m vs IMU heading (correlation -0.97)"
  std::vector<std::string> advice;     // in words
};

/// Throws std::runtime_error when the drive gives no initial state (the message says why).
ObservabilityReport analyzeObservability(const CalibrationInputs& in, const ObservabilityJob& job);

/// Antenna positions along a reference (IMU pose and lever arm p_b_g) at the given times, with
/// `sigma_m` per axis: the GNSS of a covariance analysis.
std::vector<PositionFix> antennaPositionsAlong(const ReferenceTrajectory& reference,
                                               const Eigen::Vector3d& p_b_g,
                                               const std::vector<double>& times, double sigma_m);
/// The same at each rover epoch with a base epoch, with the covariance that epoch's DD carrier
/// phase gives with its ambiguities fixed (options.dd: satellites, mask, noise); epochs without
/// three independent phase rows give none.
std::vector<PositionFix> antennaPositionsFromPhase(const ReferenceTrajectory& reference,
                                                   const Eigen::Vector3d& p_b_g,
                                                   const CalibrationInputs& in,
                                                   const CalibrationOptions& options);

}  // namespace giocal
