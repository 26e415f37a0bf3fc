#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "common/imu/imu_preintegration.h"
#include "common/io/data_error.h"
#include "common/io/sensor_logs.h"
#include "common/math/rotation.h"
#include "common/odometer/odometer_preintegration.h"
#include "common/odometer/vehicle_velocity.h"
#include "sim/sensor_errors.h"
#include "sim/simulator.h"
#include "temp_dir.h"

namespace giocal {
namespace {

// A noise-free configuration that exercises every motion: turns both ways, a turn in place, speed
// changes, and hilly terrain.
sim::SimConfig noiseFreeConfig() {
  sim::SimConfig c;
  c.terrain = {1.0, 40.0};
  c.segments = {{"stationary", 3.0},
                {"speed", 4.0, 1.2},
                {"arc", 12.0, -1.0, 6.0, "left"},
                {"straight", 8.0},
                {"figure_eight", 0.0, 1.0, 4.0},
                {"stationary", 2.0},
                {"turn_in_place", 0.0, -1.0, 0.0, "left", 120.0, 30.0}};
  c.imu = {};
  c.imu.gyro_bias_deg_h = c.imu.accel_bias_mgal = c.imu.arw_deg_sqrt_h = c.imu.vrw_m_s_sqrt_h = 0.0;
  c.odometer.speed_sigma = c.odometer.yaw_rate_sigma_deg_s = 0.0;
  c.truth.s_v = 0.02;
  c.truth.s_w = -0.03;
  c.truth.p_b_m = {0.3, -0.2, 0.15};
  c.truth.q_b_m = Eigen::Quaterniond(rotationFromRpy(Vec3(1.5, -2.0, 3.0) * kDegToRad));
  return c;
}

// Chains 1 s preintegrations of the noise-free IMU from the true initial state (gravity at each
// interval's start) and returns the worst position error against the truth over 60 s.
double worstPositionErrorOver60s(double imu_rate_hz) {
  sim::SimConfig cfg = noiseFreeConfig();
  cfg.imu.rate_hz = imu_rate_hz;
  const sim::SimulatedLogs logs = sim::simulate(cfg, 1);
  EXPECT_GT(logs.truth_n.back().t - logs.truth_n.front().t, 61.0);
  NavState s = logs.truth_n.front();
  const int per_second = static_cast<int>(imu_rate_hz);
  double worst_p = 0, worst_v = 0, worst_q = 0;
  for (int k = 0; k < 60 * per_second; k += per_second) {
    ImuPreintegration pre(ImuNoise{}, logs.frame.gravity_n(s.p_n_b), logs.frame.omega_ie_n(),
                          Vec3::Zero(), Vec3::Zero());
    const std::vector<ImuSample> window(logs.imu.begin() + k,
                                        logs.imu.begin() + k + per_second + 1);
    pre.integrateSamples(window, window.front().t, window.back().t);
    s = pre.predict(s);
    const NavState& t = logs.truth_n[static_cast<size_t>(k + per_second)];
    worst_p = std::max(worst_p, (s.p_n_b - t.p_n_b).norm());
    worst_v = std::max(worst_v, (s.v_n_b - t.v_n_b).norm());
    worst_q = std::max(worst_q, s.q_n_b.angularDistance(t.q_n_b));
  }
  EXPECT_LT(worst_v, 1e-3);
  EXPECT_LT(worst_q, 1e-5);
  return worst_p;
}

TEST(Simulator, NoiseFreeImuIntegratesToTheTruthOver60s) {
  // Turns, a figure eight, a turn in place and 1 m hills: within 1 cm at 100 Hz (measured 2.8
  // mm)...
  EXPECT_LT(worstPositionErrorOver60s(100.0), 0.01);
  // ...and the remainder is the integrator's sampling (coning) error, which falls with dt^2: the
  // simulated truth itself is exact (measured 0.17 mm at 400 Hz).
  EXPECT_LT(worstPositionErrorOver60s(400.0), 1e-3);
}

TEST(Simulator, NoiseFreeOdometerIsTheTrueMotionOfTheVehicleFrame) {
  const sim::SimConfig cfg = noiseFreeConfig();
  const sim::SimulatedLogs logs = sim::simulate(cfg, 1);
  ASSERT_EQ(logs.odom.size(), logs.true_speed.size());
  double worst_meas = 0, worst_nhc = 0, worst_speed = 0, worst_rate = 0;
  const int imu_per_odo = static_cast<int>(cfg.imu.rate_hz / cfg.odometer.rate_hz);
  for (size_t k = 0; k < logs.odom.size(); ++k) {
    // measured = true / (1 + s).
    worst_meas =
        std::max({worst_meas, std::abs(logs.odom[k].v * (1 + cfg.truth.s_v) - logs.true_speed[k]),
                  std::abs(logs.odom[k].w * (1 + cfg.truth.s_w) - logs.true_yaw_rate[k])});
    // The true speed and yaw rate equal the motion of m derived from the IMU truth and the
    // extrinsic (an independent path through common/): no lateral or vertical velocity.
    const size_t i = k * static_cast<size_t>(imu_per_odo);
    const NavState& s = logs.truth_n[i];
    const Vec3 w_ie_b = s.q_n_b.conjugate() * logs.frame.omega_ie_n();
    const VehicleVelocity vv = vehicleVelocity(s.v_n_b, s.q_n_b, logs.imu[i].gyro - w_ie_b,
                                               Vec3::Zero(), cfg.truth.p_b_m, cfg.truth.q_b_m);
    worst_nhc = std::max({worst_nhc, std::abs(vv.v_m.x()), std::abs(vv.v_m.z())});
    worst_speed = std::max(worst_speed, std::abs(vv.v_m.y() - logs.true_speed[k]));
    worst_rate = std::max(worst_rate, std::abs(vv.w_m.z() - logs.true_yaw_rate[k]));
  }
  EXPECT_LT(worst_meas, 1e-12);
  EXPECT_LT(worst_nhc, 1e-9);
  EXPECT_LT(worst_speed, 1e-9);
  EXPECT_LT(worst_rate, 1e-9);
}

TEST(Simulator, OdometerPreintegrationFitsTheNoiseFreeTruth) {
  // The integral odometer measurement over 1 s intervals, at the true IMU poses and calibration
  // (the preintegration is linearized at the true scales, so its first-order s_w term vanishes).
  sim::SimConfig cfg = noiseFreeConfig();
  cfg.terrain = {0.0, 40.0};  // planar: the odometer sees no tilt
  const sim::SimulatedLogs logs = sim::simulate(cfg, 1);
  const int imu_per_s = static_cast<int>(cfg.imu.rate_hz);
  OdometerCalibration c{cfg.truth.s_v, cfg.truth.s_w, cfg.truth.p_b_m, cfg.truth.q_b_m};
  double worst_p = 0, worst_q = 0;
  for (size_t k = 0; k + static_cast<size_t>(imu_per_s) < logs.truth_n.size();
       k += static_cast<size_t>(imu_per_s)) {
    const NavState& a = logs.truth_n[k];
    const NavState& b = logs.truth_n[k + static_cast<size_t>(imu_per_s)];
    OdometerPreintegration pre({}, c.s_v, c.s_w);
    pre.integrateSamples(logs.odom, a.t, b.t);
    const OdometerResidual r = pre.evaluate(a.p_n_b, a.q_n_b, b.p_n_b, b.q_n_b, c);
    worst_p = std::max(worst_p, r.r.head<3>().norm());
    worst_q = std::max(worst_q, r.r.tail<3>().norm());
  }
  // Measured 1.5e-4 m and 1.1e-4 rad, at segment transitions where the readings are not linear
  // between samples (a zero-order hold gave 1.7e-2 m and 9e-3 rad).
  EXPECT_LT(worst_p, 1e-3);
  EXPECT_LT(worst_q, 5e-4);
  std::printf("odometer preintegration at the truth: worst %.2e m, %.2e rad\n", worst_p, worst_q);
}

TEST(Simulator, NoisyPresetHasTheConfiguredErrorLevels) {
  sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml");
  const sim::SimulatedLogs noisy = sim::simulate(cfg, 5);
  cfg.odometer.speed_sigma = cfg.odometer.yaw_rate_sigma_deg_s = 0.0;
  const sim::SimulatedLogs clean = sim::simulate(cfg, 5);
  double sv = 0, sw = 0;
  for (size_t k = 0; k < noisy.odom.size(); ++k) {
    sv += std::pow(noisy.odom[k].v - clean.odom[k].v, 2);
    sw += std::pow(noisy.odom[k].w - clean.odom[k].w, 2);
  }
  const double n = static_cast<double>(noisy.odom.size());
  EXPECT_NEAR(std::sqrt(sv / n), 0.01, 0.001);
  EXPECT_NEAR(std::sqrt(sw / n), 1.0 * kDegToRad, 0.1 * kDegToRad);
  // Paper duration and speeds: about 150 s, 0.25 m/s once moving.
  EXPECT_NEAR(noisy.truth.back().t - noisy.truth.front().t, 150.0, 1.0);
  EXPECT_NEAR(clean.true_speed[static_cast<size_t>(30 * 25)], 0.25, 1e-9);
  EXPECT_EQ(clean.true_speed[static_cast<size_t>(10 * 25)], 0.0);
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(Simulator, SameSeedGivesIdenticalFilesAndTheReadersAcceptThem) {
  test::TempDir dir;
  const sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml");
  sim::writeDataset(sim::simulate(cfg, 7), dir.file("a"));
  sim::writeDataset(sim::simulate(cfg, 7), dir.file("b"));
  sim::writeDataset(sim::simulate(cfg, 8), dir.file("c"));
  for (const char* f : {"imu.csv", "odom.csv", "truth.csv", "dataset.yaml", "truth_calib.yaml",
                        "rover.obs", "base.obs", "nav.rnx"}) {
    const std::string a = slurp(dir.file("a") + "/" + f);
    EXPECT_FALSE(a.empty()) << f;
    EXPECT_EQ(a, slurp(dir.file("b") + "/" + f)) << f;
  }
  EXPECT_NE(slurp(dir.file("a") + "/imu.csv"), slurp(dir.file("c") + "/imu.csv"));
  EXPECT_NE(slurp(dir.file("a") + "/rover.obs"), slurp(dir.file("c") + "/rover.obs"));
  // Everything written reads back through the checked readers.
  const DatasetDescription d = readDatasetDescription(dir.file("a"));
  EXPECT_EQ(readImuCsv(d.pathOf(d.imu)).size(), 15001u);
  EXPECT_EQ(readOdomCsv(d.pathOf(d.odom)).size(), 3751u);
  EXPECT_EQ(readTruthCsv(d.pathOf(d.truth)).size(), 15001u);
  const TruthCalibration t = readTruthCalibration(dir.file("a") + "/truth_calib.yaml");
  EXPECT_DOUBLE_EQ(t.calib.s_v, 0.02);
  // The initial guess differs from the truth by a draw of the configured sigma.
  EXPECT_GT((d.initial_calibration.mean.p_b_m - t.calib.p_b_m).norm(), 1e-3);
  EXPECT_LT((d.initial_calibration.mean.p_b_m - t.calib.p_b_m).norm(), 5 * 0.5 * std::sqrt(3.0));
}

TEST(Simulator, BadConfigIsReportedWithFileAndLine) {
  test::TempDir dir;
  const std::string good = slurp(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml");
  std::string bad = good;
  bad.replace(bad.find("type: arc"), 9, "type: spiral");
  const std::string path = dir.write("bad.yaml", bad);
  try {
    sim::readSimConfig(path);
    FAIL();
  } catch (const DataError& e) {
    EXPECT_GT(e.line(), 0);
    EXPECT_NE(std::string(e.what()).find("spiral"), std::string::npos) << e.what();
  }
  EXPECT_THROW(sim::parseGpsTime("2024-13-01 00:00:00"), std::invalid_argument);
  EXPECT_THROW(sim::parseGpsTime("yesterday"), std::invalid_argument);
}

// Every key of a preset is read or refused: the field preset's wheel-slip lines were ignored
// without a word until 2026-11-26. A misspelling, at the top, in a segment or in a scene, names
// its line and the nearest key.
TEST(SimConfig, EveryKeyIsReadOrRefusedByName) {
  test::TempDir dir;
  std::string paper = slurp(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml");
  paper.replace(paper.find("nav_file: ../../data/"), 21,
                "nav_file: " + std::string(GIOCAL_SOURCE_DIR) + "/data/");
  std::string slipping = paper;
  slipping.replace(slipping.find("odometer:\n"), 10,
                   "odometer:\n  slip_rate_per_min: 3.0\n  slip_duration_s: 0.2\n"
                   "  slip_speed_factor: 1.4\n");
  const sim::SimConfig c = sim::readSimConfig(dir.write("slip.yaml", slipping));
  EXPECT_EQ(c.odometer.slip_rate_per_min, 3.0);
  EXPECT_EQ(c.odometer.slip_duration_s, 0.2);
  EXPECT_EQ(c.odometer.slip_speed_factor, 1.4);
  const std::vector<std::pair<std::string, std::string>> misspelt{
      {"  rate_hz: 25", "odometer.rate_hz"},
      {"transition: 2.0", "s.transition"},
  };
  for (const auto& [text, nearest] : misspelt) {
    std::string bad = paper;
    const size_t at = bad.find(text);
    ASSERT_NE(at, std::string::npos) << text;
    bad.insert(at + text.find(':'), "x");
    try {
      sim::readSimConfig(dir.write("bad.yaml", bad));
      ADD_FAILURE() << "accepted a misspelt " << text;
    } catch (const DataError& e) {
      EXPECT_GT(e.line(), 0) << e.what();
      EXPECT_NE(std::string(e.what()).find("did you mean '" + nearest + "'"), std::string::npos)
          << e.what();
    }
  }
  // A base of another make: its signals are read, and a bad one is named by its place.
  std::string mixed = paper;
  mixed.replace(
      mixed.find("  systems: GEC"), 14,
      "  systems: GECJ\n  base_phase_aligned: 0\n  base_signals:\n"
      "    - {signal: G2W, min_elevation_deg: 25}\n    - {signal: J1X, shift_cycles: 0.25}");
  const sim::SimConfig m = sim::readSimConfig(dir.write("mixed.yaml", mixed));
  ASSERT_EQ(m.gnss.base_signals.size(), 2u);
  EXPECT_EQ(m.gnss.base_signals[1].sys, GnssSystem::kQzss);
  EXPECT_EQ(m.gnss.base_signals[1].attr, 'X');
  EXPECT_EQ(m.gnss.base_signals[1].shift_cycles, 0.25);
  EXPECT_EQ(m.gnss.base_signals[0].min_elevation_deg, 25.0);
  EXPECT_FALSE(m.gnss.base_phase_aligned);
  for (const auto& [from, to, says] :
       std::vector<std::tuple<std::string, std::string, std::string>>{
           {"signal: J1X", "signal: J9X", "'gnss.base_signals[1].signal': 'J9X'"},
           {"signal: J1X", "signal: R1C", "'gnss.base_signals[1].signal': 'R1C'"},
           {"shift_cycles: 0.25", "shift: 0.25", "unknown key 'gnss.base_signals[1].shift'"},
           {"shift_cycles: 0.25", "shift_cycles: 2", "value 2 outside [-0.5, 0.5]"},
           {"signal: J1X", "signal: G2W", "'G2W' is listed twice"}}) {
    std::string bad = mixed;
    bad.replace(bad.find(from), from.size(), to);
    try {
      sim::readSimConfig(dir.write("bad.yaml", bad));
      ADD_FAILURE() << "accepted " << to;
    } catch (const DataError& e) {
      EXPECT_GT(e.line(), 0) << e.what();
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace giocal

namespace giocal {
namespace {

// A fuzzer-found timeout (issue 23): the loop's segments were read from the YAML again for every
// lap, so a preset of 1000 laps took 3 s to read (over 5 s under the sanitizers).
TEST(SimConfig, ManyLapsReadFast) {
  std::ifstream in(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/field.yaml");
  std::stringstream text;
  text << in.rdbuf();
  std::string preset =
      std::regex_replace(text.str(), std::regex("\\n  laps: [0-9]+"), "\n  laps: 1000");
  preset = std::regex_replace(
      preset, std::regex("nav_file: [^ \\n]+"),
      "nav_file: " + std::string(GIOCAL_SOURCE_DIR) + "/data/real/mosaic-static-nagoya/base.nav");
  test::TempDir dir;
  const std::string path = dir.write("many_laps.yaml", preset);
  const auto t0 = std::chrono::steady_clock::now();
  const sim::SimConfig c = sim::readSimConfig(path);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(c.segments.size(), 2u + 4u * 1000u);
  EXPECT_LT(s, 0.5);
}

}  // namespace
}  // namespace giocal

namespace giocal {
namespace {

// The truth states the extrinsic of the IMU's measuring axes: the mean of the rotations that the
// gyro and accelerometer triads apply to what they measure (each recovered here from noise-free
// measurements of the three unit vectors), and truth_calib / truth.csv rotate with it.
TEST(ImuMeasuringAxes, TruthIsStatedInTheMeanOfTheGyroAndAccelerometerAxes) {
  sim::ImuErrorSpec spec;
  spec.gyro_bias_deg_h = spec.accel_bias_mgal = spec.arw_deg_sqrt_h = spec.vrw_m_s_sqrt_h = 0.0;
  spec.misalignment_deg = 1.0;
  std::mt19937_64 rng(7);
  sim::ImuErrors errors(spec, rng);
  Mat3 R_g, R_a;
  for (int i = 0; i < 3; ++i) {
    const ImuSample s = errors.measure(0.0, Vec3::Unit(i), Vec3::Unit(i), 0.01, rng);
    R_g.col(i) = s.gyro;
    R_a.col(i) = s.acc;
  }
  EXPECT_GT(logSO3(R_g.transpose() * R_a).norm(), 0.1 * kDegToRad);  // the triads differ
  const Mat3 M = errors.measuringAxes();
  EXPECT_LT((logSO3(M) - 0.5 * (logSO3(R_g) + logSO3(R_a))).norm(), 1e-12);

  sim::SimConfig c = noiseFreeConfig();
  const sim::SimulatedLogs ideal = sim::simulate(c, 3);
  EXPECT_LT(
      (ideal.truth_calib.calib.q_b_m.toRotationMatrix() - c.truth.q_b_m.toRotationMatrix()).norm(),
      1e-12);
  c.imu.misalignment_deg = 1.0;
  const sim::SimulatedLogs tilted = sim::simulate(c, 3);
  const Mat3 R_a_b = tilted.truth_calib.calib.q_b_m.toRotationMatrix() *
                     c.truth.q_b_m.toRotationMatrix().transpose();
  EXPECT_GT(logSO3(R_a_b).norm(), 0.1 * kDegToRad);
  EXPECT_LT((tilted.truth_calib.calib.p_b_m - R_a_b * c.truth.p_b_m).norm(), 1e-12);
  // truth.csv's attitude is that of the same measuring axes.
  const Mat3 R_b_a = ideal.truth_n.front().q_n_b.toRotationMatrix().transpose() *
                     tilted.truth_n.front().q_n_b.toRotationMatrix();
  EXPECT_LT((R_b_a - R_a_b.transpose()).norm(), 1e-9);
}

}  // namespace
}  // namespace giocal
