// SimConfig: everything `giocal simulate` needs, in data-sheet units as a preset states them,
// with defaults in one place; loaded from config/sim/*.yaml.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "common/odometer/odometer_calibration.h"
#include "sim/gnss_simulator.h"
#include "sim/motion_profile.h"
#include "sim/trajectory.h"

namespace giocal::sim {

struct ImuErrorSpec {
  double rate_hz = 100.0;
  double gyro_bias_deg_h = 900.0;          // turn-on bias, 1-sigma per axis [deg/h]
  double accel_bias_mgal = 5.0;            // turn-on bias, 1-sigma per axis [mGal = 1e-5 m/s^2]
  double arw_deg_sqrt_h = 20.0;            // angle random walk [deg/sqrt(h)]
  double vrw_m_s_sqrt_h = 0.1;             // velocity random walk [m/s/sqrt(h)]
  double gyro_bias_rw_deg_h_sqrt_h = 0.0;  // bias random walk [deg/h/sqrt(h)]
  double accel_bias_rw_mgal_sqrt_s = 0.0;  // bias random walk [mGal/sqrt(s)]
  double scale_ppm = 0.0;                  // scale factor error, 1-sigma per axis [ppm]
  double misalignment_deg = 0.0;           // axis misalignment, 1-sigma [deg]
};

struct OdometerErrorSpec {
  double rate_hz = 25.0;
  double speed_sigma = 0.01;            // white noise [m/s]
  double yaw_rate_sigma_deg_s = 1.0;    // white noise [deg/s]
  double scale_drift_per_sqrt_s = 0.0;  // random walk of s_v and s_w [1/sqrt(s)]
  double speed_quantum = 0.0;           // measurement resolution [m/s]; 0 = none
  double yaw_rate_quantum_deg_s = 0.0;
  double slip_rate_per_min = 0.0;  // wheel-slip events per minute of driving
  double slip_duration_s = 0.5;    // length of one event [s]
  double slip_speed_factor = 1.3;  // measured / true speed while slipping (wheels spin)
  double delay_s = 0.0;  // stamps late by this (a wheel driver's latency; dataset.yaml not told)
};

struct SimConfig {
  std::string name = "sim";
  std::string start_time = "2024-06-24 08:20:30";  // GPST, inside data/real nav validity
  double origin_lat_deg = 35.1347;                 // start of the trajectory
  double origin_lon_deg = 136.9776;
  double origin_h = 60.0;
  double initial_heading_deg = 30.0;  // yaw of m at the start (from north towards west)
  Terrain terrain;
  std::vector<SegmentSpec> segments;
  ImuErrorSpec imu;
  OdometerErrorSpec odometer;
  OdometerCalibration truth;  // true s_v, s_w, p_b_m, q_b_m
  Eigen::Vector3d p_b_g{0.0, 0.0, 0.5};
  GnssSimSpec gnss;  // gnss.enabled = false when the config has no gnss section
  // 1-sigma of the initial calibration guess drawn around the truth (written to dataset.yaml).
  double guess_sd_s_v = 0.02, guess_sd_s_w = 0.02;
  double guess_sd_p_b_m = 0.5;    // [m]
  double guess_sd_rpy_deg = 5.0;  // [deg]
};

/// Throws DataError naming the file, line and problem.
SimConfig readSimConfig(const std::string& path);

}  // namespace giocal::sim
