// The observability advisor's IMU along a reference: idealImuAlong() gives what the simulator's
// error-free IMU gives (rate, specific force, Earth rate, Coriolis, gravity), and with it the
// advisor's expected sigmas no longer depend on the IMU's noise: the paper preset's noisy gyro
// made its extrinsic yaw look 1.7 times better known than noise-free data of the same drive.
#include <gtest/gtest.h>

#include <cmath>

#include "common/calibration/calibration_inputs.h"
#include "common/io/sensor_logs.h"
#include "common/math/rotation.h"
#include "evaluation/ideal_imu.h"
#include "evaluation/observability.h"
#include "sim/simulator.h"
#include "temp_dir.h"

namespace giocal {
namespace {

sim::SimConfig paper(bool imu_errors) {
  sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml");
  if (!imu_errors) {
    cfg.imu.arw_deg_sqrt_h = cfg.imu.vrw_m_s_sqrt_h = 0.0;
    cfg.imu.gyro_bias_deg_h = cfg.imu.accel_bias_mgal = 0.0;
  }
  return cfg;
}

TEST(IdealImu, IsTheSimulatorsErrorFreeImu) {
  test::TempDir dir;
  sim::writeDataset(sim::simulate(paper(false), 91), dir.file("data"));
  const CalibrationInputs in = loadCalibrationInputs(dir.file("data"));
  const ReferenceTrajectory ref(readTruthCsv(dir.file("data") + "/truth.csv"));
  const std::vector<ImuSample> ideal = idealImuAlong(ref, in.imu);
  ASSERT_EQ(ideal.size(), in.imu.size());
  double gyro = 0.0, acc = 0.0;
  for (std::size_t k = 1; k + 1 < ideal.size(); ++k) {
    gyro = std::max(gyro, (ideal[k].gyro - in.imu[k].gyro).norm());
    acc = std::max(acc, (ideal[k].acc - in.imu[k].acc).norm());
  }
  std::cout << "ideal IMU against the simulator's error-free IMU: gyro " << gyro << " rad/s, acc "
            << acc << " m/s^2 at most\n";
  // The paper's gyro noise is 0.06 rad/s per sample, its accelerometer's 0.017 m/s^2.
  EXPECT_LT(gyro, 5e-5);
  EXPECT_LT(acc, 5e-5);
}

TEST(Observability, TheImusNoiseIsNotTakenForInformation) {
  test::TempDir dir;
  CalibrationInputs in[2];
  for (const bool imu_errors : {false, true}) {
    const std::string data = dir.file(imu_errors ? "noisy" : "clean");
    sim::writeDataset(sim::simulate(paper(imu_errors), 92), data);
    in[imu_errors] = loadCalibrationInputs(data);
  }
  // The advisor is told the same IMU noise for both (the noisy IMU's).
  in[0].description.imu_noise = in[1].description.imu_noise;
  double yaw[2] = {0.0, 0.0};
  for (int k : {0, 1}) {
    ObservabilityJob job;
    job.linearize_at = in[k].truth->calib;
    job.reference =
        ReferenceTrajectory(readTruthCsv(dir.file(k ? "noisy" : "clean") + "/truth.csv"));
    std::vector<double> times;
    for (const ObsEpoch& e : in[k].rover.epochs) times.push_back(e.t);
    in[k].positions = antennaPositionsAlong(*job.reference, in[k].truth->p_b_g, times, 0.01);
    yaw[k] = analyzeObservability(in[k], job).expected_sigma[7];
  }
  std::cout << "expected extrinsic yaw sigma: noise-free IMU " << yaw[0] << " deg, noisy " << yaw[1]
            << " deg\n";
  EXPECT_NEAR(yaw[1] / yaw[0], 1.0, 0.05);
  EXPECT_GT(yaw[0], 3.5);  // degrees: most of the 5-degree prior stays (the Monte Carlo's 4.6)
}

}  // namespace
}  // namespace giocal
