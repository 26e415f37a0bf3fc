#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "common/calibration/calibration_run.h"
#include "common/calibration/run_writer.h"
#include "common/io/data_error.h"
#include "common/io/output_set.h"
#include "common/math/rotation.h"
#include "evaluation/calibration_source.h"
#include "evaluation/dead_reckoning.h"
#include "replay/replay.h"
#include "sim/simulator.h"
#include "temp_dir.h"

namespace giocal {
namespace {

/// Two laps of the field preset (about 260 s), loaded, with its truth as the reference.
struct Drive {
  test::TempDir dir;
  CalibrationInputs in;
  std::unique_ptr<ReferenceTrajectory> reference;
  explicit Drive(std::uint64_t seed) {
    sim::SimConfig cfg =
        sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/field.yaml");
    cfg.segments.resize(2 + 2 * 4);
    sim::writeDataset(sim::simulate(cfg, seed), dir.file("data"));
    in = loadCalibrationInputs(dir.file("data"));
    reference = std::make_unique<ReferenceTrajectory>(readTruthCsv(dir.file("data/truth.csv")));
  }
  DeadReckoning run(const OdometerCalibration& calib,
                    const Eigen::Matrix<double, 8, 8>& covariance =
                        Eigen::Matrix<double, 8, 8>::Identity() * 1e-14) const {
    DeadReckoningJob job;
    job.start_s = 40.0;
    job.duration_s = 200.0;
    job.calibration.mean = calib;
    job.calibration.covariance = covariance;
    return deadReckon(in, *reference, job);
  }
};

TEST(DeadReckoning, StartsOnTheReferenceAndAScaleErrorShowsAsTheSameShareOfTheDistance) {
  const Drive drive(61);
  const OdometerCalibration truth = drive.in.truth->calib;
  const DeadReckoning exact = drive.run(truth);
  ASSERT_FALSE(exact.errors.empty());
  EXPECT_LT(exact.errors.front().horizontal(), 1e-6);  // moved onto the reference at the start
  EXPECT_NEAR(exact.errors.back().elapsed, 200.0, 0.11);
  EXPECT_GT(exact.distance_m, 250.0);  // 1.5 m/s, stops and turns
  EXPECT_GT(exact.aided_s, 10.0);
  EXPECT_LE(exact.horizontal_rmse_m, exact.horizontal_max_m);
  // The odometer's distance scale wrong by 2 %: the along-track error grows to about 2 % of the
  // distance; with the true calibration it stays several times smaller.
  OdometerCalibration scaled = truth;
  scaled.s_v += 0.02;
  const DeadReckoning wrong = drive.run(scaled);
  EXPECT_GT(wrong.horizontal_max_m, 3.0 * exact.horizontal_max_m);
  EXPECT_GT(wrong.final_error_percent_of_distance, 0.5);
  EXPECT_LT(wrong.final_error_percent_of_distance, 3.0);
  // A yaw error of the IMU mounting of 2 degrees: a heading error the odometer integrates (on a
  // closed loop the lateral errors of opposite sides partly cancel: 2.6x on seed 61).
  OdometerCalibration yawed = truth;
  yawed.q_b_m = truth.q_b_m *
                Eigen::Quaterniond(Eigen::AngleAxisd(2.0 * M_PI / 180.0, Eigen::Vector3d::UnitZ()));
  EXPECT_GT(drive.run(yawed).horizontal_max_m, 2.0 * exact.horizontal_max_m);
}

// One receiver's own track as the reference (validate --gnss single): its offset, metres, is
// taken out at the window's start, and nothing after its first gap is compared (the track's next
// stretch starts at another single point position).
TEST(DeadReckoning, RelativeToItsStartAnOffsetReferenceGivesTheSameErrorsUpToItsFirstGap) {
  const Drive drive(62);
  const std::vector<TruthSample> rows = readTruthCsv(drive.dir.file("data/truth.csv"));
  std::vector<TruthSample> moved = rows;
  for (TruthSample& r : moved) {
    r.lat_deg += 5.0 / 6378137.0 * kRadToDeg;  // 5 m north
    r.h += 2.0;
  }
  DeadReckoningJob job;
  job.start_s = 40.0;
  job.duration_s = 120.0;
  job.calibration.mean = drive.in.truth->calib;
  job.calibration.covariance = Eigen::Matrix<double, 8, 8>::Identity() * 1e-14;
  job.reference_has_attitude = false;  // a GNSS solution: the aided start state is kept
  const DeadReckoning absolute = deadReckon(drive.in, ReferenceTrajectory(moved), job);
  job.relative_to_start = true;
  const DeadReckoning plain = deadReckon(drive.in, ReferenceTrajectory(rows), job);
  const DeadReckoning relative = deadReckon(drive.in, ReferenceTrajectory(moved), job);
  ASSERT_FALSE(relative.errors.empty());
  EXPECT_GT(absolute.errors.front().horizontal(), 4.5);
  EXPECT_LT(relative.errors.front().horizontal(), 1e-9);
  EXPECT_NEAR(relative.horizontal_max_m, plain.horizontal_max_m, 1e-3);
  EXPECT_LT(relative.horizontal_max_m, 1.0);
  EXPECT_NEAR(relative.errors.back().elapsed, 120.0, 0.2);

  // A 2 s gap in the reference 50 s in: compared up to it, not after.
  std::vector<TruthSample> gapped;
  for (const TruthSample& r : moved) {
    if (r.t < relative.t_start + 50.0 || r.t > relative.t_start + 52.0) gapped.push_back(r);
  }
  const DeadReckoning cut = deadReckon(drive.in, ReferenceTrajectory(gapped), job);
  EXPECT_NEAR(cut.errors.back().elapsed, 50.0, 0.2);
}

// A calibrate run's covariance correlates the extrinsic yaw with the lever arm and the scales.
// The initial state's attitude is correlated with the extrinsic yaw, so it must be with everything
// that is: with the theta block alone the joint covariance was indefinite, and the dead reckoning
// with the EKF's calibration of this paper-preset drive drifted by 552 m in 80 s.
TEST(DeadReckoning, ARunsCorrelatedCovarianceKeepsTheFilterSound) {
  test::TempDir dir;
  sim::writeDataset(
      sim::simulate(sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml"),
                    1),
      dir.file("data"));
  const CalibrationInputs in = loadCalibrationInputs(dir.file("data"));
  const CalibrationRun run = replayInputs(in, {"ekf", CalibrationOptions{}, {}}, nullptr);
  ASSERT_TRUE(run.latest.has_value());
  const ReferenceTrajectory reference(readTruthCsv(dir.file("data/truth.csv")));
  DeadReckoningJob job;
  job.start_s = 60.0;
  job.duration_s = 80.0;
  job.calibration.mean = run.latest->calib;
  job.calibration.covariance = run.latest->cov;
  const DeadReckoning correlated = deadReckon(in, reference, job);
  job.calibration.covariance = Eigen::Matrix<double, 8, 8>(run.latest->cov.diagonal().asDiagonal());
  const DeadReckoning diagonal = deadReckon(in, reference, job);
  EXPECT_LT(correlated.horizontal_max_m, 1.0);
  EXPECT_LT(correlated.horizontal_max_m, 2.0 * diagonal.horizontal_max_m + 0.2);
}

TEST(CalibrationSource, ReadsRunsRowsTruthAndGuessAndSaysWhatIsWrong) {
  const Drive drive(62);
  const test::TempDir& dir = drive.dir;
  // A run's output set, written as calibrate writes it.
  CalibrationRun run;
  run.estimator = "ekf";
  CalibrationEstimate e;
  e.t = drive.in.rover.epochs.front().t + 50.0;
  e.calib.s_v = 0.012;
  e.calib.p_b_m = Eigen::Vector3d(0.1, -0.2, 0.3);
  e.cov = Eigen::Matrix<double, 8, 8>::Identity() * 4e-6;
  run.latest = e;
  {
    OutputSet set(dir.file("run"));
    RunWriter writer(set);
    writer.estimate(e);
    CalibrationEstimate later = e;
    later.t += 100.0;
    later.calib.s_v = 0.02;
    writer.estimate(later);
    writer.finish(run, nullptr);
    set.commit();
  }
  const CalibrationSource s = readCalibrationSource(dir.file("run/summary.json"), drive.in);
  EXPECT_NEAR(s.calibration.mean.s_v, 0.012, 1e-12);
  ASSERT_TRUE(s.calibration.covariance);
  EXPECT_NEAR((*s.calibration.covariance)(3, 3), 4e-6, 1e-15);
  EXPECT_EQ(s.odometer_delay_s, 0.0);  // not estimated by that run
  const CalibrationSource at60 =
      readCalibrationSource(dir.file("run/calibration.csv@60"), drive.in);
  EXPECT_NEAR(at60.calibration.mean.s_v, 0.012, 1e-12);
  EXPECT_NEAR(at60.calibration.sd_p_b_m.y(), 2e-3, 1e-9);
  const CalibrationSource at200 =
      readCalibrationSource(dir.file("run/calibration.csv@200"), drive.in);
  EXPECT_NEAR(at200.calibration.mean.s_v, 0.02, 1e-12);
  EXPECT_THROW(readCalibrationSource(dir.file("run/calibration.csv@10"), drive.in), DataError);
  // A run that estimated the odometer's delay hands it on (deadreckon shifts the stamps by it).
  {
    CalibrationRun with_delay = run;
    with_delay.latest->odometer_delay_s = 0.031;
    with_delay.latest->odometer_delay_sd_s = 0.002;
    OutputSet set(dir.file("delay"));
    RunWriter writer(set);
    writer.estimate(e);
    writer.finish(with_delay, nullptr);
    set.commit();
  }
  EXPECT_EQ(readCalibrationSource(dir.file("delay/summary.json"), drive.in).odometer_delay_s,
            0.031);
  // A run whose data started 100 s earlier than these data (another drive): its own start counts.
  run.t_first_rover_epoch = drive.in.rover.epochs.front().t - 100.0;
  {
    OutputSet set(dir.file("other"));
    RunWriter writer(set);
    writer.estimate(e);
    writer.finish(run, nullptr);
    set.commit();
  }
  EXPECT_THROW(readCalibrationSource(dir.file("other/calibration.csv@60"), drive.in), DataError);
  EXPECT_NEAR(
      readCalibrationSource(dir.file("other/calibration.csv@160"), drive.in).calibration.mean.s_v,
      0.012, 1e-12);
  EXPECT_THROW(readCalibrationSource(dir.file("run/calibration.csv@ten"), drive.in),
               std::runtime_error);
  EXPECT_EQ(readCalibrationSource("truth", drive.in).calibration.mean.s_w,
            drive.in.truth->calib.s_w);
  EXPECT_EQ(readCalibrationSource("guess", drive.in).calibration.mean.s_v,
            drive.in.description.initial_calibration.mean.s_v);
  // A summary beside a calibration.csv of another run is refused.
  std::ofstream(dir.file("run/calibration.csv"), std::ios::app) << "1,2,3\n";
  EXPECT_THROW(readCalibrationSource(dir.file("run/summary.json"), drive.in), DataError);
  EXPECT_THROW(readCalibrationSource("nonsense", drive.in), std::runtime_error);
}

TEST(CalibrationSource, ARowOfCalibrationCsvBringsTheDelayAndGyroTiltOfItsTime) {
  // calibration.csv's columns are the brief's: the optional states' histories lie beside it, and
  // a row taken from it must bring them (the dead-reckoning bench takes each scene's calibration
  // so; without them its rows dropped an estimated tilt that the truth's row applied).
  const Drive drive(62);
  const test::TempDir& dir = drive.dir;
  CalibrationRun run;
  run.estimator = "fgo";
  CalibrationEstimate e;
  e.t = drive.in.rover.epochs.front().t + 50.0;
  e.cov = Eigen::Matrix<double, 8, 8>::Identity() * 4e-6;
  e.odometer_delay_s = 0.031;
  e.odometer_delay_sd_s = 0.002;
  e.gyro_tilt = Eigen::Vector2d(0.01, -0.02) * kDegToRad;
  e.gyro_tilt_sd = Eigen::Vector2d(0.004, 0.005) * kDegToRad;
  {
    OutputSet set(dir.file("run"));
    RunWriter writer(set);
    writer.estimate(e);
    CalibrationEstimate later = e;
    later.t += 100.0;
    later.odometer_delay_s = 0.041;
    later.gyro_tilt = Eigen::Vector2d(0.03, 0.04) * kDegToRad;
    writer.estimate(later);
    run.latest = later;
    writer.finish(run, nullptr);
    set.commit();
  }
  std::ifstream header_of(dir.file("run/gyro_tilt.csv"));
  std::string header;
  std::getline(header_of, header);
  EXPECT_EQ(header, "t,tilt_x,tilt_y,sd_tilt_x,sd_tilt_y");
  const CalibrationSource at60 =
      readCalibrationSource(dir.file("run/calibration.csv@60"), drive.in);
  EXPECT_NEAR(at60.odometer_delay_s, 0.031, 1e-12);
  EXPECT_NEAR(at60.gyro_tilt.x() * kRadToDeg, 0.01, 1e-12);
  EXPECT_NEAR(at60.gyro_tilt.y() * kRadToDeg, -0.02, 1e-12);
  EXPECT_NEAR(at60.gyro_tilt_sd * kRadToDeg, 0.005, 1e-12);
  const CalibrationSource at200 =
      readCalibrationSource(dir.file("run/calibration.csv@200"), drive.in);
  EXPECT_NEAR(at200.odometer_delay_s, 0.041, 1e-12);
  EXPECT_NEAR(at200.gyro_tilt.y() * kRadToDeg, 0.04, 1e-12);
  // The end of the run from its summary.json: the same values as its last row.
  const CalibrationSource end = readCalibrationSource(dir.file("run/summary.json"), drive.in);
  EXPECT_NEAR(end.gyro_tilt.y(), at200.gyro_tilt.y(), 1e-12);
  EXPECT_NEAR(end.odometer_delay_s, at200.odometer_delay_s, 1e-12);
  // A history that is not one (another header) is named.
  std::ofstream(dir.file("run/gyro_tilt.csv")) << "t,x,y\n";
  EXPECT_THROW(readCalibrationSource(dir.file("run/calibration.csv@60"), drive.in), DataError);
}

}  // namespace
}  // namespace giocal
