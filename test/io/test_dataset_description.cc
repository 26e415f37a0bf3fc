#include <gtest/gtest.h>

#include <fstream>

#include "common/io/data_error.h"
#include "common/io/dataset_description.h"
#include "common/io/dataset_folder.h"
#include "common/math/rotation.h"
#include "temp_dir.h"

namespace giocal {
namespace {

DatasetDescription sampleDescription(const std::string& folder) {
  DatasetDescription d;
  d.folder = folder;
  d.nav = {"nav1.rnx", "nav2.rnx"};
  d.truth = "truth.csv";
  d.imu_noise.gyro_noise_density = 0.0058;
  d.odom_noise.yaw_rate_sigma = 0.02;
  d.p_b_g = {0.1, -0.2, 0.5};
  d.base_position_ecef = Eigen::Vector3d(-3978241.958, 3382840.234, 3649900.853);
  d.initial_calibration.mean.s_v = 0.01;
  d.initial_calibration.mean.p_b_m = {0.2, -0.3, 0.1};
  d.initial_calibration.mean.q_b_m = Eigen::Quaterniond(rotationFromRpy({0.01, -0.02, 0.05}));
  d.initial_calibration.sd_rpy_b_m = Eigen::Vector3d(5, 5, 5) * kDegToRad;
  return d;
}

TEST(DatasetDescription, RoundTrip) {
  test::TempDir dir;
  const DatasetDescription d = sampleDescription(dir.path());
  writeDatasetDescription(d);
  const DatasetDescription r = readDatasetDescription(dir.path());
  EXPECT_EQ(r.nav, d.nav);
  EXPECT_EQ(r.truth, "truth.csv");
  EXPECT_DOUBLE_EQ(r.imu_noise.gyro_noise_density, 0.0058);
  EXPECT_DOUBLE_EQ(r.odom_noise.yaw_rate_sigma, 0.02);
  EXPECT_LT((r.p_b_g - d.p_b_g).norm(), 1e-12);
  ASSERT_TRUE(r.base_position_ecef.has_value());
  EXPECT_LT((*r.base_position_ecef - *d.base_position_ecef).norm(), 1e-6);
  EXPECT_DOUBLE_EQ(r.initial_calibration.mean.s_v, 0.01);
  EXPECT_LT(r.initial_calibration.mean.q_b_m.angularDistance(d.initial_calibration.mean.q_b_m),
            1e-9);
  EXPECT_LT((r.initial_calibration.sd_rpy_b_m - d.initial_calibration.sd_rpy_b_m).norm(), 1e-12);
  EXPECT_EQ(r.pathOf(r.imu), dir.path() + "/imu.csv");
}

TEST(DatasetDescription, MissingKeyAndBadValuesNameTheLine) {
  test::TempDir dir;
  writeDatasetDescription(sampleDescription(dir.path()));
  std::ifstream in(dir.file("dataset.yaml"));
  const std::string good((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());

  auto expectError = [&](const std::string& content, const std::string& what) {
    dir.write("dataset.yaml", content);
    try {
      readDatasetDescription(dir.path());
      FAIL() << "accepted: " << what;
    } catch (const DataError& e) {
      EXPECT_EQ(e.file(), dir.file("dataset.yaml"));
      EXPECT_GT(e.line(), 0) << e.what();
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  auto replace = [&](const std::string& from, const std::string& to) {
    std::string s = good;
    const auto pos = s.find(from);
    EXPECT_NE(pos, std::string::npos) << from;
    return s.replace(pos, from.size(), to);
  };
  expectError(replace("  speed_sigma:", "  speed_sigmaa:"), "missing key 'odometer.speed_sigma'");
  expectError(replace("gyro_noise_density: 0.0058", "gyro_noise_density: fast"),
              "must be a number");
  expectError(replace("gyro_noise_density: 0.0058", "gyro_noise_density: -1"), "outside");
  expectError(replace("gyro_noise_density: 0.0058", "gyro_noise_density: .nan"), "not finite");
  expectError(replace("p_b_g: [0.1, -0.2, 0.5]", "p_b_g: [0.1, -0.2]"), "list of 3 finite numbers");
  expectError(replace("base_position_ecef: [", "base_position_ecef: [1, 2, 3] #"), "ECEF");
  expectError(replace("files:", "files: [\n"), "YAML syntax error");
  expectError(good + "deep: " + std::string(5000, '[') + std::string(5000, ']') + "\n",
              "YAML nested too deeply");
  expectError("- 1\n- 2\n", "the document is a list; expected a map of keys");
  expectError("just a sentence\n", "the document is a single value; expected a map of keys");
  expectError("", "the document is empty; expected a map of keys");
  expectError(good + "[a, b]: 3\n", "a key under 'the top level' is a list or a map");
  // An optional key misspelt is refused, not left at its default.
  expectError(good + "time_offsets:\n  odometr: 0.05\n",
              "unknown key 'time_offsets.odometr'; did you mean 'time_offsets.odometer'?");
}

TEST(TruthCalibration, RoundTripAndConsistency) {
  test::TempDir dir;
  TruthCalibration t;
  t.calib.s_v = 0.02;
  t.calib.s_w = -0.03;
  t.calib.p_b_m = {0.3, -0.2, 0.1};
  t.calib.q_b_m = Eigen::Quaterniond(rotationFromRpy(Vec3(2, -1, 3) * kDegToRad));
  t.p_b_g = {0, 0.1, 0.8};
  writeTruthCalibration(dir.file("truth_calib.yaml"), t);
  const TruthCalibration r = readTruthCalibration(dir.file("truth_calib.yaml"));
  EXPECT_DOUBLE_EQ(r.calib.s_w, -0.03);
  EXPECT_LT(r.calib.q_b_m.angularDistance(t.calib.q_b_m), 1e-12);
  EXPECT_LT((r.p_b_g - t.p_b_g).norm(), 1e-15);
  // q_b_m and rpy_b_m_deg that disagree are rejected.
  dir.write(
      "bad.yaml",
      "s_v: 0\ns_w: 0\np_b_m: [0,0,0]\nq_b_m: [1,0,0,0]\nrpy_b_m_deg: [0,0,10]\np_b_g: [0,0,0]\n");
  EXPECT_THROW(readTruthCalibration(dir.file("bad.yaml")), DataError);
  dir.write("noq.yaml", "s_v: 0\ns_w: 0\np_b_m: [0,0,0]\np_b_g: [0,0,0]\n");
  EXPECT_THROW(readTruthCalibration(dir.file("noq.yaml")), DataError);
}

TEST(DatasetFolder, NamesTheFilesItLacksAndReadsTheDescriptionOnce) {
  test::TempDir dir;
  DatasetDescription d = sampleDescription(dir.path());
  writeDatasetDescription(d);
  std::ofstream(dir.file("imu.csv"))
      << "t,wx,wy,wz,ax,ay,az\n10,0,0,0,0,0,9.8\n12.5,0,0,0,0,0,9.8\n";
  std::ofstream(dir.file("nav2.rnx")) << "";
  const DatasetFolder data = openDatasetFolder(dir.path());
  // odom.csv, rover.obs, base.obs, truth.csv and nav1.rnx are named and not there.
  EXPECT_EQ(data.missing, (std::vector<std::string>{"odom.csv", "rover.obs", "base.obs",
                                                    "truth.csv", "nav1.rnx"}));
  EXPECT_DOUBLE_EQ(data.imu_span.first, 10.0);
  EXPECT_DOUBLE_EQ(data.imu_span.second, 12.5);
  EXPECT_EQ(data.description.nav, d.nav);
  EXPECT_TRUE(data.findings.empty());  // only giocal check fills them
  EXPECT_FALSE(data.hasTruthTrajectory());
}

}  // namespace
}  // namespace giocal
