#include "apps/import_i2nav.h"

#include <iomanip>
#include <nlohmann/json.hpp>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "common/gnss/pos_file.h"
#include "common/io/data_error.h"
#include "common/io/dataset_description.h"
#include "common/io/output_set.h"
#include "common/io/sensor_logs.h"
#include "common/math/rotation.h"
#include "import/i2nav_text.h"

namespace giocal {
namespace {

const std::vector<std::string> kI2navFiles{"imu.csv",   "odom.csv",     "gnss.pos",
                                           "truth.csv", "dataset.yaml", "import.json"};
constexpr double kOdometerPeriod = 0.05;  // [s]: the speed column is averaged to 20 Hz

// The text files say nothing of the sensors' noise: the values i2Nav publishes for the weakest
// IMU of awesome-gins-datasets (ICM20602: ARW 0.2 deg/sqrt(h), VRW 0.2 m/s/sqrt(h), bias
// sigmas 200 deg/h and 1000 mGal, first-order Gauss-Markov with a 1 h correlation time, whose
// driving noise is sigma sqrt(2 / tau)); edit dataset.yaml for a better IMU.
ImuNoise defaultImuNoise() {
  ImuNoise n;
  const double tau = 3600.0;
  n.gyro_noise_density = 0.2 * kDegToRad / 60.0;
  n.accel_noise_density = 0.2 / 60.0;
  n.gyro_bias_sigma = 200.0 * kDegToRad / 3600.0;
  n.accel_bias_sigma = 1000.0e-5;
  n.gyro_bias_random_walk = n.gyro_bias_sigma * std::sqrt(2.0 / tau);
  n.accel_bias_random_walk = n.accel_bias_sigma * std::sqrt(2.0 / tau);
  return n;
}

Eigen::Vector3d parseLeverArm(const std::string& text) {
  Eigen::Vector3d v;
  char c1 = 0, c2 = 0;
  std::istringstream in(text);
  if (!(in >> v.x() >> c1 >> v.y() >> c2 >> v.z()) || c1 != ',' || c2 != ',' || !v.allFinite() ||
      v.cwiseAbs().maxCoeff() > 10.0) {
    throw std::runtime_error("--lever-arm '" + text + "' is not x,y,z in metres (each under 10)");
  }
  return v;
}

}  // namespace

void importI2nav(const ImportJob& job, std::ostream& log) {
  refuseToOverwrite(job, kI2navFiles);
  int week = job.gps_week;
  if (week < 0) {
    if (job.i2nav_nav.empty()) {
      throw std::runtime_error(
          "the i2Nav IMU text has seconds of week only: give --gps-week or --i2nav-nav");
    }
    week = import::firstWeekOfI2navNav(job.i2nav_nav);
  }
  import::I2navImu imu = import::readI2navImu(job.i2nav_imu, week, kOdometerPeriod);
  if (imu.columns == 7) {
    throw DataError(job.i2nav_imu, 0,
                    "7 columns: no odometer speed (an 8th column), and giocal calibrates an "
                    "odometer against the IMU");
  }
  std::vector<std::string> warnings = imu.warnings;
  std::vector<RtkSolution> fixes;
  if (!job.i2nav_pos.empty()) fixes = import::readI2navPos(job.i2nav_pos, week, &warnings);
  std::vector<TruthSample> truth;
  if (!job.i2nav_nav.empty()) truth = import::readI2navNav(job.i2nav_nav, &warnings);
  if (fixes.empty()) warnings.push_back("no --i2nav-pos: calibrate has no GNSS to calibrate from");
  log << "giocal import: " << job.i2nav_imu << "\n";

  OutputSet outputs(job.out);
  DatasetDescription desc;
  desc.rover_obs = desc.base_obs = "";  // positions, not raw GNSS: the LC scheme
  desc.nav.clear();
  desc.imu_noise = defaultImuNoise();
  desc.odom_noise.speed_sigma = 0.05;  // an unknown car's wheel speed
  // w comes from the gyro sample nearest the odometer's (the calibrator's): its noise.
  desc.odom_noise.yaw_rate_sigma = desc.imu_noise.gyro_noise_density / std::sqrt(imu.period);
  desc.odom_noise.measures_yaw_rate = false;
  // i2Nav's IMU frame is forward-right-down, aligned with the vehicle; giocal's vehicle frame m
  // is right-forward-up: m's axes in b are (0,1,0), (1,0,0), (0,0,-1).
  Eigen::Matrix3d R_b_m;
  R_b_m << 0, 1, 0, 1, 0, 0, 0, 0, -1;
  CalibrationPrior& prior = desc.initial_calibration;
  prior.mean.q_b_m = Eigen::Quaterniond(R_b_m);
  prior.sd_rpy_b_m = Eigen::Vector3d::Constant(3.0 * kDegToRad);
  if (!job.lever_arm.empty()) {
    desc.p_b_g = parseLeverArm(job.lever_arm);
  } else {
    warnings.push_back("no --lever-arm: the GNSS antenna is taken at the IMU (gnss.p_b_g 0)");
  }
  if (!truth.empty()) desc.truth = "truth.csv";

  writeImuCsv(outputs.stagedPath("imu.csv"), imu.imu);
  writeOdomCsv(outputs.stagedPath("odom.csv"), imu.odom);
  nlohmann::ordered_json files = {{"imu.csv", outputs.close("imu.csv")},
                                  {"odom.csv", outputs.close("odom.csv")}};
  if (!fixes.empty()) {
    PosHeader h;
    h.program = "giocal import (i2Nav GNSS positions)";
    h.inputs = {job.i2nav_pos};
    writePosFile(outputs.stagedPath("gnss.pos"), h, fixes);
    files["gnss.pos"] = outputs.close("gnss.pos");
  }
  if (!truth.empty()) {
    writeTruthCsv(outputs.stagedPath("truth.csv"), truth);
    files["truth.csv"] = outputs.close("truth.csv");
  }
  files["dataset.yaml"] = stageDatasetDescription(outputs, desc);
  nlohmann::ordered_json j;
  j["files"] = files;
  j["source"] = {{"imu", job.i2nav_imu}, {"pos", job.i2nav_pos}, {"nav", job.i2nav_nav}};
  j["gps_week"] = week;
  j["imu"] = {{"columns", imu.columns},
              {"samples", imu.imu.size()},
              {"period_s", imu.period},
              {"stamps", "the middle of each increment's interval"}};
  j["odometer"] = {{"samples", imu.odom.size()},
                   {"period_s", kOdometerPeriod},
                   {"speed_columns", imu.columns - 7},
                   {"measures_yaw_rate", false}};
  j["positions"] = fixes.size();
  j["truth_rows"] = truth.size();
  j["mounting"] = "i2Nav IMU frame forward-right-down, aligned with the vehicle (3 deg sigma)";
  j["warnings"] = warnings;
  outputs.open("import.json", true) << std::setprecision(12) << j.dump(2) << "\n";
  outputs.commit();

  log << std::fixed << std::setprecision(1) << "  " << imu.imu.size() << " IMU samples ("
      << imu.columns << " columns, " << 1.0 / imu.period << " Hz), " << imu.odom.size()
      << " odometer speeds (20 Hz, no yaw rate: w from the gyro, s_w not calibrated), "
      << fixes.size() << " positions, " << truth.size() << " reference rows over "
      << imu.imu.back().t - imu.imu.front().t << " s\n";
  log.unsetf(std::ios::fixed);
  for (const std::string& w : warnings) log << "  warning: " << w << "\n";
  log << "  outputs: " << job.out << "/{imu.csv, odom.csv, " << (fixes.empty() ? "" : "gnss.pos, ")
      << (truth.empty() ? "" : "truth.csv, ") << "dataset.yaml, import.json}\n";
}

}  // namespace giocal
