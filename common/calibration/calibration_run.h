// CalibrationRun: what a calibrator produced (the calibration over time with its covariance, the
// trajectory, counts and warnings), its errors against a known truth, and the writer of the
// brief's output files: calibration.csv, trajectory.csv and summary.json.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <map>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "common/calibration/fix_heights.h"
#include "common/calibration/odometer_delay.h"
#include "common/calibration/position_residuals.h"
#include "common/calibration/run_counter.h"
#include "common/geodesy/wgs84.h"
#include "common/imu/nav_state.h"
#include "common/io/dataset_description.h"
#include "common/io/sensor_logs.h"
#include "common/odometer/odometer_calibration.h"

namespace giocal {

/// Tangent order of the calibration covariance: s_v, s_w, p_b_m (3), theta_b_m (3), where the
/// rotation error is q_b_m = q_true * Exp(theta).
namespace calib_index {
constexpr int kSv = 0, kSw = 1, kP = 2, kTheta = 5, kSize = 8;
}

struct CalibrationEstimate {
  double t = 0.0;
  OdometerCalibration calib;
  Eigen::Matrix<double, 8, 8> cov = Eigen::Matrix<double, 8, 8>::Zero();
  // The odometer's delay against the IMU and its 1-sigma, when estimated (else NaN) [s].
  double odometer_delay_s = NAN, odometer_delay_sd_s = NAN;
  // The gyro triad's tilt against the accelerometer's (GyroTilt) [rad], when estimated.
  Eigen::Vector2d gyro_tilt = Eigen::Vector2d::Constant(NAN);
  Eigen::Vector2d gyro_tilt_sd = Eigen::Vector2d::Constant(NAN);

  /// 1-sigma of roll, pitch and yaw of R_b_m [rad], mapped from the tangent covariance.
  Eigen::Vector3d rpySigma() const;
  /// 1-sigma of s_v, s_w, p_b_m (x, y, z) [m], roll, pitch, yaw [deg]: the order of
  /// calibration.csv.
  Eigen::Matrix<double, 8, 1> sigma() const;
};

/// One GNSS outage window of a validation (evaluation/validation.h).
struct ValidationWindow {
  double start_s = 0.0;  // seconds after the first rover epoch
  double duration_s = 0.0, distance_m = 0.0;
  double calibrated_m = 0.0, guess_m = 0.0;  // horizontal MAX error inside the window
};

/// What `calibrate` found when it validated its own calibration at its end (evaluation/
/// validation.h): dead reckoning through GNSS outage windows with it and with the guess.
struct RunValidation {
  std::string verdict;  // "better", "no better", "worse"; empty when not validated
  std::string why_not;  // why it was not validated (a short drive, no GNSS reference, ...)
  double calibrated_m = 0.0, guess_m = 0.0, ratio = 0.0, confidence = 0.0;
  int better_windows = 0, windows = 0;
  std::string reference;  // what the windows were checked against
  std::vector<ValidationWindow> per_window;
};

/// The windows as summary.json lists them (`validate`'s "windows", `calibrate`'s
/// "validation.per_window").
nlohmann::ordered_json validationWindowsJson(const std::vector<ValidationWindow>& windows);

struct CalibrationRun {
  std::string estimator;                      // "ekf" or "fgo"
  std::optional<CalibrationEstimate> latest;  // the newest calibration estimate
  double data_duration_s = 0.0;
  double t_first_rover_epoch =
      NAN;                     // data time the "seconds after the start" of outputs count from
  double wall_time_s = 0.0;    // calibrator time: reading files and writing outputs excluded
  double load_time_s = 0.0;    // reading and checking the dataset files
  double t_initialized = 0.0;  // time of the first estimated state
  int gnss_epochs = 0;         // rover epochs used with a base epoch
  int fixed_epochs = 0;        // of those, epochs with validated ambiguity fixes
  std::string p_b_m_z;         // how the unobservable p_b_m.z was treated
  std::map<std::string, double> initialization;  // static window, heading baseline and sigma
  CounterMap counters;                           // Counter names -> tallies
  std::map<std::string, double> timing;          // wall time of parts of the run [s]
  std::map<std::string, double> converged_at;    // parameter -> data time it converged [s]
  // The odometer's delay against the IMU seen in the yaw rate both measure, after the dataset's
  // time_offsets (OdometerDelayEstimator); samples 0 when not computed.
  OdometerDelay odometer_delay;
  // The delay a first pass measured and this run took out of the odometer's stamps (calibrate's
  // calibration.apply_odometer_delay_*) [s]; 0 when none.
  double odometer_delay_applied_s = 0.0;
  // The LC solutions' heights checked against the IMU and odometer before the run
  // (fix_heights.h), and the scale this run put on their height sigmas (0: none).
  std::optional<FixHeights> lc_heights;
  double lc_height_scale_applied = 0.0;
  // The LC solutions against the run's trajectory (position_residuals.h): how far the run's
  // sigmas understate what they support.
  std::optional<PositionResiduals> lc_residuals;
  // The robot the calibration belongs to (warm_start.h's robotFingerprint of dataset.yaml): a
  // later drive's --prior is refused when it differs.
  std::map<std::string, double> robot;
  std::optional<RunValidation> validation;     // calibrate's check on its own drive
  std::vector<std::string> warnings;           // bad data met on the way, divergence (capped)
  std::map<std::string, std::string> options;  // the options in effect, defaults included
  // "ok", or "partial: <why>" when the data after a divergence or an IMU gap allowed no restart:
  // the calibration is then the last one before it.
  std::string status = "ok";

  double fixRate() const { return gnss_epochs ? double(fixed_epochs) / gnss_epochs : 0.0; }
  void count(Counter c, long n = 1) {
    const char* name = counterName(c);
    auto it = counters.find(name);
    if (it == counters.end()) it = counters.emplace(name, 0).first;
    it->second += n;
  }
  long counter(Counter c) const;
  /// Adds a warning; after kMaxWarnings the rest are only counted as omitted.
  void warn(const std::string& w);
  /// The newest estimate; throws std::logic_error when the run has none.
  const CalibrationEstimate& final() const;
  static constexpr size_t kMaxWarnings = 20;
};

/// Estimate minus truth: scales, p_b_m [m], roll/pitch/yaw difference [rad], the tangent error
/// and its NEES over the seven observable states (X, Y, roll, pitch, yaw, s_v, s_w).
struct CalibrationError {
  double s_v = 0.0, s_w = 0.0;
  Eigen::Vector3d p_b_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d rpy = Eigen::Vector3d::Zero();
  Eigen::Matrix<double, 8, 1> tangent = Eigen::Matrix<double, 8, 1>::Zero();
  double nees7 = 0.0;
};
CalibrationError calibrationError(const CalibrationEstimate& estimate,
                                  const OdometerCalibration& truth);
/// How far the calibration moved from `before` to `after`, as a chi-square in `before`'s
/// covariance over the seven observable states. In a linear estimator one update's step is
/// bounded by its innovation's chi-square, so a large one means data that disagree.
double calibrationStepChi2(const CalibrationEstimate& before, const CalibrationEstimate& after);

/// summary.json of a run (the brief's keys and giocal's, see the README), `truth` when known;
/// `files` (name -> bytes) are the other files of its output set (io/output_set.h).
std::string summaryJson(const CalibrationRun& run, const OdometerCalibration* truth,
                        const std::map<std::string, std::uintmax_t>& files = {});

/// The calibration.csv header and the row of one estimate.
const std::vector<std::string>& calibrationCsvHeader();
std::vector<double> calibrationCsvRow(const CalibrationEstimate& e);
/// The header of gyro_tilt.csv and of odometer_delay.csv, the histories of the optional states
/// beside calibration.csv (degrees; seconds).
const std::vector<std::string>& gyroTiltCsvHeader();
const std::vector<std::string>& odometerDelayCsvHeader();

/// A navigation state of the local frame n (origin `frame`) as a truth.csv row: IMU origin in
/// degrees and metres, velocity and attitude in the local-level ENU frame at that position.
TruthSample truthRow(const LocalFrame& frame, const NavState& x, double t);

/// d rpy(q Exp(theta)) / d theta (numeric): maps tangent covariances to roll/pitch/yaw and back.
Eigen::Matrix3d rpyTangentJacobian(const Eigen::Quaterniond& q);

/// The names of the files writeCalibrationRun() writes.
std::vector<std::string> calibrationOutputFiles();

}  // namespace giocal
