// DatasetDescription: the content of a dataset's dataset.yaml (file names, sensor noise, GNSS
// lever arm, base position, initial calibration guess and its sigma), and truth_calib.yaml.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "common/odometer/odometer_calibration.h"

namespace giocal {

/// Continuous-time IMU noise, as a data sheet states it (SI units).
struct ImuNoise {
  double gyro_noise_density = 1e-3;      // angle random walk [rad/s/sqrt(Hz)]
  double accel_noise_density = 1e-2;     // velocity random walk [m/s^2/sqrt(Hz)]
  double gyro_bias_random_walk = 1e-5;   // [rad/s^2/sqrt(Hz)]
  double accel_bias_random_walk = 1e-4;  // [m/s^3/sqrt(Hz)]
  double gyro_bias_sigma = 5e-3;         // initial 1-sigma [rad/s]
  double accel_bias_sigma = 5e-2;        // initial 1-sigma [m/s^2]
};

struct OdometerNoise {
  double speed_sigma = 0.01;        // white noise of the measured speed [m/s]
  double yaw_rate_sigma = 0.01745;  // white noise of the measured yaw rate [rad/s]
  double scale_random_walk = 0.0;   // random walk of s_v and s_w [1/sqrt(s)]
  // false: a speed-only odometer (a car's wheel speed, an i2Nav text log); odom.csv's w column
  // is not read, the heading change comes from the gyro and s_w stays at its prior.
  bool measures_yaw_rate = true;
};

/// Prior on the calibration: the initial guess and its 1-sigma.
struct CalibrationPrior {
  OdometerCalibration mean;
  double sd_s_v = 0.05;
  double sd_s_w = 0.05;
  Eigen::Vector3d sd_p_b_m = Eigen::Vector3d::Constant(0.5);       // [m]
  Eigen::Vector3d sd_rpy_b_m = Eigen::Vector3d::Constant(0.0873);  // [rad]
  // The full tangent covariance [s_v, s_w, p_b_m, theta_b_m] when the prior is an earlier
  // estimate carried over (a restart after an IMU gap); it then replaces the sigmas above.
  std::optional<Eigen::Matrix<double, 8, 8>> covariance;
};

/// Fixed offsets added to a sensor's time stamps to put them on the GNSS time [s]: an odometer
/// whose stamps are 50 ms late (a ROS wheel driver's latency) has odometer: -0.05.
struct TimeOffsets {
  double imu = 0.0;
  double odometer = 0.0;
  double positions = 0.0;  // the LC scheme's position solutions (an imported bag's gnss.pos)
  bool any() const { return imu != 0.0 || odometer != 0.0 || positions != 0.0; }
};

struct DatasetDescription {
  std::string folder;  // absolute or relative folder the file names below are relative to
  std::string rover_obs = "rover.obs";  // empty: no raw GNSS (an imported bag of IMU and odometry)
  std::string base_obs = "base.obs";
  std::vector<std::string> nav{"nav.rnx"};
  std::string imu = "imu.csv";
  std::string odom = "odom.csv";
  std::string truth;  // empty when the dataset has no truth
  ImuNoise imu_noise;
  OdometerNoise odom_noise;
  Eigen::Vector3d p_b_g = Eigen::Vector3d::Zero();    // GNSS antenna in b [m]
  std::optional<Eigen::Vector3d> base_position_ecef;  // [m]; else the base RINEX header
  CalibrationPrior initial_calibration;
  TimeOffsets time_offsets;  // optional section time_offsets

  std::string pathOf(const std::string& name) const { return folder + "/" + name; }
  /// Raw GNSS of a rover and no base: the single-receiver scheme's data.
  bool roverAlone() const { return !rover_obs.empty() && base_obs.empty(); }
};

/// The true calibration of a simulated dataset (truth_calib.yaml).
struct TruthCalibration {
  OdometerCalibration calib;
  Eigen::Vector3d p_b_g = Eigen::Vector3d::Zero();
  // The gyro triad's tilt against the accelerometer's (GyroTilt, degrees); NaN when not stated.
  Eigen::Vector2d gyro_tilt_deg = Eigen::Vector2d::Constant(NAN);
};

/// Throws DataError naming dataset.yaml when the dataset has no raw GNSS (files.rover_obs or
/// files.base_obs empty), which calibration needs.
void requireRawGnss(const DatasetDescription& d);

/// Reads <folder>/dataset.yaml. Throws DataError naming the file, line and problem.
DatasetDescription readDatasetDescription(const std::string& folder);
/// Writes <folder>/dataset.yaml atomically.
void writeDatasetDescription(const DatasetDescription& d);

TruthCalibration readTruthCalibration(const std::string& path);
void writeTruthCalibration(const std::string& path, const TruthCalibration& t);

}  // namespace giocal
