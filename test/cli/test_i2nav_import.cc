// giocal import --i2nav-imu: a simulated drive written in the i2Nav text formats (a forward-right-
// down IMU's increments with an odometer speed column, GNSS positions, reference navigation)
// imports to the same samples, and calibrates with its speed-only odometer by the LC scheme.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>

#include "common/geodesy/wgs84.h"
#include "common/io/dataset_description.h"
#include "common/io/sensor_logs.h"
#include "common/math/rotation.h"
#include "common/time/gps_time.h"
#include "replay/replay.h"
#include "run_giocal.h"
#include "sim/simulator.h"
#include "temp_dir.h"

namespace giocal {
namespace {

// The simulator's IMU axes are about the vehicle's (right, forward, up); i2Nav's are forward,
// right, down: b' = R b.
Eigen::Matrix3d frdFromSim() {
  Eigen::Matrix3d R;
  R << 0, 1, 0, 1, 0, 0, 0, 0, -1;
  return R;
}

struct I2navFiles {
  std::string imu, pos, nav;
};

// One text row of numbers.
void row(std::ofstream& out, const std::vector<double>& v) {
  char buf[64];
  for (size_t k = 0; k < v.size(); ++k) {
    std::snprintf(buf, sizeof buf, k == 0 ? "%.9f" : " %.15g", v[k]);
    out << buf;
  }
  out << "\n";
}

I2navFiles writeI2nav(const sim::SimulatedLogs& logs, const test::TempDir& dir) {
  const Eigen::Matrix3d R = frdFromSim();
  const I2navFiles f{dir.file("imu.txt"), dir.file("gnss.txt"), dir.file("truth.nav")};
  const auto sow = [](double t) { return weekTimeFromGpsSeconds(t).tow; };
  std::ofstream imu(f.imu), pos(f.pos), nav(f.nav);
  // Increments over (t_k - dt/2, t_k + dt/2], stamped at their end: the import's rate at the
  // middle of the interval is the simulator's sample at t_k.
  size_t o = 0;
  const double dt = 1.0 / 400.0, sow0 = sow(logs.imu.front().t);
  for (size_t k = 0; k < logs.imu.size(); ++k) {
    const ImuSample& s = logs.imu[k];
    while (o + 2 < logs.odom.size() && logs.odom[o + 1].t <= s.t) ++o;
    const OdomSample &a = logs.odom[o], &b = logs.odom[o + 1];
    const double speed = a.v + (b.v - a.v) * std::clamp((s.t - a.t) / (b.t - a.t), 0.0, 1.0);
    const Eigen::Vector3d dtheta = R * s.gyro * dt, dvel = R * s.acc * dt;
    row(imu, {sow0 + (static_cast<double>(k) + 0.5) * dt, dtheta.x(), dtheta.y(), dtheta.z(),
              dvel.x(), dvel.y(), dvel.z(), speed});
  }
  std::mt19937 rng(5);
  std::normal_distribution<double> n(0.0, 0.02);
  for (size_t k = 0; k < logs.gnss.rover.size(); ++k) {
    const Geodetic g = geodeticFromEcef(logs.antenna_e[k]);
    const Eigen::Matrix3d R_e_l = rotationEcefFromEnu(g.lat, g.lon);
    const Geodetic m =
        geodeticFromEcef(logs.antenna_e[k] + R_e_l * Eigen::Vector3d(n(rng), n(rng), n(rng)));
    row(pos,
        {sow(logs.gnss.rover[k].t), m.lat * kRadToDeg, m.lon * kRadToDeg, m.h, 0.02, 0.02, 0.02});
  }
  Eigen::Matrix3d R_ned_enu;
  R_ned_enu << 0, 1, 0, 1, 0, 0, 0, 0, -1;
  for (size_t k = 0; k < logs.truth.size(); k += 40) {  // 10 Hz
    const TruthSample& t = logs.truth[k];
    const Eigen::Matrix3d R_ned_b = R_ned_enu * t.q_n_b.toRotationMatrix() * R.transpose();
    const double yaw = std::atan2(R_ned_b(1, 0), R_ned_b(0, 0));
    const double pitch = -std::asin(R_ned_b(2, 0));
    const double roll = std::atan2(R_ned_b(2, 1), R_ned_b(2, 2));
    const GpsWeekTime wt = weekTimeFromGpsSeconds(t.t);
    nav << wt.week << " ";
    row(nav, {wt.tow, t.lat_deg, t.lon_deg, t.h, t.v_enu.y(), t.v_enu.x(), -t.v_enu.z(),
              roll * kRadToDeg, pitch * kRadToDeg, yaw * kRadToDeg});
  }
  return f;
}

TEST(I2navImport, ASimulatedDriveRoundTripsAndCalibratesWithItsSpeedOnlyOdometer) {
  sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/field.yaml");
  cfg.segments.resize(2 + 3 * 4);  // three laps
  const sim::SimulatedLogs logs = sim::simulate(cfg, 74);
  test::TempDir dir;
  const I2navFiles f = writeI2nav(logs, dir);
  const Eigen::Matrix3d R = frdFromSim();
  const Eigen::Vector3d lever = R * logs.truth_calib.p_b_g;
  const std::string out = dir.file("data");
  const test::GiocalResult r = test::runGiocal(
      "import --i2nav-imu " + f.imu + " --i2nav-pos " + f.pos + " --i2nav-nav " + f.nav +
      " --lever-arm " + std::to_string(lever.x()) + "," + std::to_string(lever.y()) + "," +
      std::to_string(lever.z()) + " --out " + out);
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("no yaw rate"), std::string::npos) << r.out;

  // The IMU: every sample after the first, at its time, in the FRD axes.
  const std::vector<ImuSample> imu = readImuCsv(out + "/imu.csv");
  ASSERT_EQ(imu.size(), logs.imu.size() - 1);
  double worst_t = 0.0, worst_gyro = 0.0, worst_acc = 0.0;
  for (size_t k = 0; k < imu.size(); ++k) {
    const ImuSample& s = logs.imu[k + 1];
    worst_t = std::max(worst_t, std::abs(imu[k].t - s.t));
    worst_gyro = std::max(worst_gyro, (imu[k].gyro - R * s.gyro).norm());
    worst_acc = std::max(worst_acc, (imu[k].acc - R * s.acc).norm());
  }
  // Times to the text's nanoseconds (and the simulator's GPS seconds' rounding); rates to what
  // those nanoseconds leave of the 2.5 ms intervals.
  EXPECT_LT(worst_t, 1e-6);
  EXPECT_LT(worst_gyro, 2e-6);
  EXPECT_LT(worst_acc, 2e-5);
  // The odometer at 20 Hz, speed only.
  const DatasetDescription d = readDatasetDescription(out);
  EXPECT_FALSE(d.odom_noise.measures_yaw_rate);
  const std::vector<OdomSample> odom = readOdomCsv(out + "/odom.csv");
  EXPECT_NEAR(static_cast<double>(odom.size()), (imu.back().t - imu.front().t) * 20.0, 2.0);
  // The reference: the simulator's truth at 10 Hz, attitude of the FRD axes.
  const std::vector<TruthSample> truth = readTruthCsv(out + "/truth.csv");
  ASSERT_EQ(truth.size(), (logs.truth.size() + 39) / 40);
  for (size_t k = 0; k < truth.size(); k += 100) {
    const TruthSample& t = logs.truth[40 * k];
    EXPECT_NEAR(truth[k].t, t.t, 2e-6);
    EXPECT_NEAR(truth[k].lat_deg, t.lat_deg, 1e-9);
    EXPECT_LT((truth[k].v_enu - t.v_enu).norm(), 1e-9);
    const Eigen::Matrix3d R_n_b = t.q_n_b.toRotationMatrix() * R.transpose();
    EXPECT_LT(logSO3(truth[k].q_n_b.toRotationMatrix().transpose() * R_n_b).norm(), 1e-9);
  }

  // As a user would: the IMU's own noise (the import writes i2Nav's ICM20602 figures).
  DatasetDescription edited = d;
  edited.imu_noise = logs.description.imu_noise;
  writeDatasetDescription(edited);
  // LC calibration with the speed-only odometer: s_v and the extrinsic are calibrated, their
  // sigmas cover their errors; s_w, which nothing measures, keeps its prior.
  OdometerCalibration true_calib = logs.truth_calib.calib;
  true_calib.q_b_m = Eigen::Quaterniond(R * true_calib.q_b_m.toRotationMatrix());
  true_calib.p_b_m = R * true_calib.p_b_m;
  const CalibrationInputs in = loadCalibrationInputs(out, out + "/gnss.pos");
  CalibrationOptions lc;
  lc.loosely_coupled = true;
  for (const char* estimator : {"ekf", "fgo"}) {
    SCOPED_TRACE(estimator);
    const CalibrationRun run = replayInputs(in, {estimator, lc, {}}, nullptr);
    const CalibrationError e = calibrationError(run.final(), true_calib);
    const Eigen::Matrix<double, 8, 1> sd = run.final().sigma();
    EXPECT_LT(sd[0], 0.1 * d.initial_calibration.sd_s_v);
    EXPECT_LT(std::abs(e.s_v), 4.0 * sd[0]) << e.s_v;
    EXPECT_LT(sd[3], 0.2 * d.initial_calibration.sd_p_b_m.y());
    EXPECT_LT(e.p_b_m.head<2>().norm(), 4.0 * sd.segment<2>(2).norm()) << e.p_b_m.transpose();
    // Yaw (sigma() gives the angles' in degrees).
    EXPECT_LT(sd[7], 0.5 * d.initial_calibration.sd_rpy_b_m.z() * kRadToDeg);
    EXPECT_LT(std::abs(e.rpy.z()) * kRadToDeg, 4.0 * sd[7]) << e.rpy.transpose();
    EXPECT_NEAR(run.final().calib.s_w, d.initial_calibration.mean.s_w, 1e-9);
    EXPECT_NEAR(sd[1], d.initial_calibration.sd_s_w, 1e-6);
    if (std::string(estimator) != "ekf") continue;
    // A robot's driver without a yaw rate sends NaN: taken, turned with the gyro, the same run.
    CalibrationInputs nan_w = in;
    for (OdomSample& o : nan_w.odom) o.w = NAN;
    const CalibrationRun again = replayInputs(nan_w, {estimator, lc, {}}, nullptr);
    EXPECT_EQ(again.counters.at("non_finite_samples_dropped"), 0);
    EXPECT_EQ(again.final().calib.s_v, run.final().calib.s_v);
    EXPECT_EQ(again.final().calib.p_b_m, run.final().calib.p_b_m);
  }
}

TEST(I2navImport, BadTextAnswersWithTheFileAndLine) {
  test::TempDir dir;
  const std::string out = dir.file("data");
  // No odometer column: nothing to calibrate.
  const std::string seven =
      dir.write("seven.txt", "100.0 0 0 0 0 0 0.05\n100.005 0 0 0 0 0 0.05\n");
  test::GiocalResult r =
      test::runGiocal("import --i2nav-imu " + seven + " --gps-week 2000 --out " + out);
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.out.find("seven.txt: 7 columns: no odometer speed"), std::string::npos) << r.out;
  // A word in the middle: the line.
  const std::string bad = dir.write(
      "bad.txt", "100.0 0 0 0 0 0 0.05 1\n100.005 0 0 x 0 0 0.05 1\n100.010 0 0 0 0 0 0.05 1\n");
  r = test::runGiocal("import --i2nav-imu " + bad + " --gps-week 2000 --out " + out);
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.out.find("bad.txt:2: not a number"), std::string::npos) << r.out;
  // Degrees for radians: rates far beyond a vehicle's.
  const std::string degrees =
      dir.write("degrees.txt",
                "100.0 0 0 0 0 0 0.05 1\n100.005 0 0 2.5 0 0 0.05 1\n100.010 0 0 0 0 0 0.05 1\n");
  r = test::runGiocal("import --i2nav-imu " + degrees + " --gps-week 2000 --out " + out);
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.out.find("degrees.txt:2: increments or speed beyond"), std::string::npos) << r.out;
  // No week anywhere.
  r = test::runGiocal("import --i2nav-imu " + bad + " --out " + out);
  EXPECT_NE(r.out.find("--gps-week"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(out + "/imu.csv"));
  // A truncated last line and a row out of order: dropped, each named, the rest imported.
  std::string text;
  for (int k = 0; k < 50; ++k) {
    text += std::to_string(100.0 + 0.01 * k) + " 0 0 0.0001 0 0 0.098 1.5\n";
    if (k == 20) text += "100.05 0 0 0 0 0 0.098 1.5\n";
  }
  text += "100.5 0 0";
  const std::string cut = dir.write("cut.txt", text);
  r = test::runGiocal("import --i2nav-imu " + cut + " --gps-week 2000 --out " + out);
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("cut.txt:52: truncated last line dropped"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("cut.txt:22: time not after the previous row's"), std::string::npos)
      << r.out;
  EXPECT_EQ(readImuCsv(out + "/imu.csv").size(), 49u);
}

}  // namespace
}  // namespace giocal
