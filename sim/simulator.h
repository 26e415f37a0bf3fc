// simulate(): the logs of one dataset (IMU, odometer, rover and base GNSS, truth) from a SimConfig
// and a seed, and writeDataset() to put them in a dataset folder.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "common/geodesy/wgs84.h"
#include "common/imu/imu_sample.h"
#include "common/imu/nav_state.h"
#include "common/io/dataset_description.h"
#include "common/io/scenes_csv.h"
#include "common/io/sensor_logs.h"
#include "common/odometer/odom_sample.h"
#include "sim/gnss_simulator.h"
#include "sim/sim_config.h"
#include "sim/trajectory.h"

namespace giocal::sim {

struct SimulatedLogs {
  LocalFrame frame;  // n: ENU at the trajectory start
  std::vector<ImuSample> imu;
  std::vector<OdomSample> odom;
  std::vector<TruthSample> truth;                 // truth.csv rows, at the IMU times
  std::vector<NavState> truth_n;                  // the same in n, with the true biases, for tests
  std::vector<double> true_speed, true_yaw_rate;  // of m at the odometer times
  SimulatedGnss gnss;                             // empty when the config has no gnss section
  std::string nav_file;                           // copied into the dataset as nav.rnx
  std::vector<Eigen::Vector3d> antenna_e;         // true antenna ECEF at the rover epochs
  DatasetDescription description;                 // dataset.yaml content (folder left empty)
  /// The rover's scenes in GPS time (scenes.csv), cut to the drive; empty without gnss.scenes.
  std::vector<SceneSpan> scenes;
  TruthCalibration truth_calib;
};

/// Physically exact truth (normal gravity at each position, Earth rotation, rigid mounting) and
/// realistic sensor errors. The same config and seed give identical logs.
SimulatedLogs simulate(const SimConfig& config, std::uint64_t seed);

/// The motion sensors (IMU, odometer), truth, true calibration and dataset description with its
/// initial guess of a vehicle driving `path` (its time 0 at GPS time t0, positions in frame's
/// n), with the config's sensor models and calibration; the config's gnss section is not used.
SimulatedLogs simulateMotionSensors(const SimConfig& config, const VehiclePath& path,
                                    const LocalFrame& frame, double t0, std::uint64_t seed);

/// The true antenna (at the config's p_b_g) of a vehicle driving `path` from GPS time t0, in ECEF;
/// `path` must outlive the function.
AntennaTruth antennaPath(const SimConfig& config, const VehiclePath& path, const LocalFrame& frame,
                         double t0);

/// Writes imu.csv, odom.csv, truth.csv, dataset.yaml, truth_calib.yaml and, with scenes,
/// scenes.csv (t_start,t_end,type) into `folder` (created if missing); each file atomically.
void writeDataset(const SimulatedLogs& logs, const std::string& folder);

/// Parses "yyyy-mm-dd hh:mm:ss[.sss]" (GPST) into GPS seconds; throws std::invalid_argument.
double parseGpsTime(const std::string& text);

}  // namespace giocal::sim
