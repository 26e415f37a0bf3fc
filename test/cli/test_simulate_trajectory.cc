// giocal simulate --trajectory: a simulated drive's own RINEX with its true antenna positions as
// the given solution. The fitted path runs where the simulator's vehicle ran, and the dataset
// built on it calibrates as the simulator's own does (sigmas covering the errors).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "common/geodesy/wgs84.h"
#include "common/gnss/pos_file.h"
#include "common/io/sensor_logs.h"
#include "common/math/rotation.h"
#include "replay/replay.h"
#include "run_giocal.h"
#include "sim/simulator.h"
#include "temp_dir.h"

namespace giocal {
namespace {

TEST(SimulateTrajectory, TheSimulatorsOwnGnssAndAntennaPathGiveItsDriveAndCalibration) {
  const std::string preset = std::string(GIOCAL_SOURCE_DIR) + "/config/sim/field.yaml";
  sim::SimConfig cfg = sim::readSimConfig(preset);
  cfg.segments.resize(2 + 3 * 4);  // three laps
  const sim::SimulatedLogs logs = sim::simulate(cfg, 93);
  test::TempDir dir;
  sim::writeDataset(logs, dir.file("sim"));
  std::vector<RtkSolution> antenna;
  for (size_t k = 0; k < logs.gnss.rover.size(); ++k) {
    RtkSolution s;
    s.t = logs.gnss.rover[k].t;
    s.quality = 1;
    s.p_e = logs.antenna_e[k];
    s.cov_e = Eigen::Matrix3d::Identity() * 2.5e-5;  // 5 mm
    antenna.push_back(s);
  }
  writePosFile(dir.file("antenna.pos"), PosHeader{}, antenna);

  // The preset gives the sensor models and calibration; the path comes from the solution.
  const std::string out = dir.file("along");
  const test::GiocalResult r = test::runGiocal(
      "simulate --config " + preset + " --seed 93 --trajectory " + dir.file("antenna.pos") +
      " --rover " + dir.file("sim/rover.obs") + " --base " + dir.file("sim/base.obs") + " --nav " +
      dir.file("sim/nav.rnx") + " --out " + out);
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("knots every 2.000 s"), std::string::npos) << r.out;
  // The path's antenna against the solutions: within millimetres but in the turn-ins, which
  // knots every 2 s round off by centimetres.
  const size_t at = r.out.find("solutions: median ");
  ASSERT_NE(at, std::string::npos) << r.out;
  double median = 1.0, max = 1.0;
  ASSERT_EQ(std::sscanf(r.out.c_str() + at, "solutions: median %lf m, max %lf m", &median, &max),
            2);
  EXPECT_LT(median, 0.002);
  EXPECT_LT(max, 0.05);

  // The synthesized IMU runs where the simulator's did (both truth.csv hold the IMU origin and
  // attitude in the local level): the path's smoothing is all that differs.
  const std::vector<TruthSample> a = readTruthCsv(dir.file("sim/truth.csv"));
  const std::vector<TruthSample> b = readTruthCsv(out + "/truth.csv");
  ASSERT_GT(b.size(), 100000u);
  double worst_p = 0.0, worst_q = 0.0, sum_q2 = 0.0;
  int n = 0;
  size_t i = 0;
  for (size_t k = 0; k < b.size(); k += 400) {
    while (i + 1 < a.size() && a[i].t < b[k].t - 1e-6) ++i;
    ASSERT_NEAR(a[i].t, b[k].t, 1e-6);
    const Eigen::Vector3d pa =
        ecefFromGeodetic({a[i].lat_deg * kDegToRad, a[i].lon_deg * kDegToRad, a[i].h});
    const Eigen::Vector3d pb =
        ecefFromGeodetic({b[k].lat_deg * kDegToRad, b[k].lon_deg * kDegToRad, b[k].h});
    worst_p = std::max(worst_p, (pa - pb).norm());
    const double dq =
        logSO3(a[i].q_n_b.toRotationMatrix().transpose() * b[k].q_n_b.toRotationMatrix()).norm();
    worst_q = std::max(worst_q, dq);
    sum_q2 += dq * dq;
    ++n;
  }
  // Knots every 2 s (the solution's 1 Hz) round the 2 s turn-ins: the heading there is up to
  // 1.5 degrees off the simulator's, the position a few centimetres.
  const double rms_q = std::sqrt(sum_q2 / n);
  std::cout << "path against the simulator's: position max " << worst_p << " m, attitude max "
            << worst_q * kRadToDeg << " deg, rms " << rms_q * kRadToDeg << " deg\n";
  EXPECT_LT(worst_p, 0.05);
  EXPECT_LT(worst_q * kRadToDeg, 2.0);
  EXPECT_LT(rms_q * kRadToDeg, 0.5);

  // Calibrated from the real (here: simulated) GNSS and the synthesized sensors: the sigmas
  // cover the errors, as in the Monte Carlo.
  const CalibrationInputs in = loadCalibrationInputs(out);
  ASSERT_TRUE(in.truth.has_value());
  for (const char* estimator : {"ekf", "fgo"}) {
    SCOPED_TRACE(estimator);
    const CalibrationRun run = replayInputs(in, {estimator, {}, {}}, nullptr);
    EXPECT_GT(run.fixRate(), 0.9);
    const CalibrationError e = calibrationError(run.final(), in.truth->calib);
    const Eigen::Matrix<double, 8, 1> sd = run.final().sigma();
    EXPECT_LT(sd[0], 0.05 * in.description.initial_calibration.sd_s_v);
    EXPECT_LT(std::abs(e.s_v), 4.0 * sd[0]) << e.s_v;
    EXPECT_LT(std::abs(e.s_w), 4.0 * sd[1]) << e.s_w;
    EXPECT_LT(e.p_b_m.head<2>().norm(), 4.0 * sd.segment<2>(2).norm()) << e.p_b_m.transpose();
    EXPECT_LT(std::abs(e.rpy.z()) * kRadToDeg, 4.0 * sd[7]) << e.rpy.transpose();
    EXPECT_LT(e.nees7, 24.32);  // chi-square, 7 dof, 99.9 % (measured 13.1 and 12.7)
  }
}

TEST(SimulateTrajectory, AClearWordForWhatItCannotUse) {
  test::TempDir dir;
  const std::string preset = std::string(GIOCAL_SOURCE_DIR) + "/config/sim/field.yaml";
  test::GiocalResult r = test::runGiocal("simulate --config " + preset + " --trajectory " +
                                         dir.file("none.pos") + " --out " + dir.file("x"));
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.out.find("--trajectory needs --rover and --nav"), std::string::npos) << r.out;
  // Four solutions: no path.
  std::vector<RtkSolution> few(4);
  for (size_t k = 0; k < few.size(); ++k) {
    few[k].t = 1.4e9 + static_cast<double>(k);
    few[k].quality = 1;
    few[k].p_e = ecefFromGeodetic({0.6, 2.4, 30.0});
    few[k].cov_e = Eigen::Matrix3d::Identity() * 1e-4;
  }
  writePosFile(dir.file("few.pos"), PosHeader{}, few);
  const std::string obs = dir.write("x.obs", "");
  r = test::runGiocal("simulate --config " + preset + " --trajectory " + dir.file("few.pos") +
                      " --rover " + obs + " --base " + obs + " --nav " + obs + " --out " +
                      dir.file("x"));
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.out.find("few.pos: fewer than 10 fixed or float solutions"), std::string::npos)
      << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir.file("x/dataset.yaml")));
}

}  // namespace
}  // namespace giocal
