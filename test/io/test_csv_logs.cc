#include <gtest/gtest.h>

#include <filesystem>

#include "common/io/data_error.h"
#include "common/io/sensor_logs.h"
#include "temp_dir.h"

namespace giocal {
namespace {

// Expects `fn` to throw a DataError whose message names the file, the line and contains `what`.
template <typename Fn>
void expectDataError(Fn fn, const std::string& file, long line, const std::string& what) {
  try {
    fn();
    FAIL() << "no error for " << what;
  } catch (const DataError& e) {
    EXPECT_EQ(e.file(), file);
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "message must be one line";
  }
}

const std::string kImuHeader = "t,wx,wy,wz,ax,ay,az\n";

TEST(ImuCsv, RoundTrip) {
  test::TempDir dir;
  std::vector<ImuSample> s(3);
  for (int k = 0; k < 3; ++k) {
    s[k].t = 1.4e9 + 0.01 * k;
    s[k].gyro = {0.1 * k, -0.2, 1.0 / 3.0};
    s[k].acc = {0.0, 0.1, 9.80665 + k};
  }
  writeImuCsv(dir.file("imu.csv"), s);
  const auto back = readImuCsv(dir.file("imu.csv"));
  ASSERT_EQ(back.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(back[k].t, s[k].t);
    EXPECT_EQ(back[k].gyro, s[k].gyro);
    EXPECT_EQ(back[k].acc, s[k].acc);
  }
  // No temporary file is left beside the output.
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir.path()))
    files += e.is_regular_file();
  EXPECT_EQ(files, 1);
}

TEST(ImuCsv, RejectsBadInputWithFileAndLine) {
  test::TempDir dir;
  const std::string ok = "1.0,0,0,0,0,0,9.8\n";
  struct Case {
    std::string content;
    long line;
    std::string what;
  };
  const std::vector<Case> cases{
      {"", 0, "header missing"},
      {"t,wx,wy,wz,ax,ay\n" + ok, 1, "header must be"},
      {kImuHeader + ok + "2.0,0,0,0,0,9.8\n3.0,0,0,0,0,0,9.8\n", 3,
       "expected 7 columns, found 6"},  // a short line that is not the last: structure
      {kImuHeader + ok + "2.0,0,0,0,0,0,9.8,1\n", 3, "expected 7 columns, found 8"},
      {kImuHeader + ok + "nan,0,0,0,0,0,9.8\n", 3, "time is not finite"},
      {kImuHeader + ok + "2.0,0,0,abc,0,0,9.8\n", 3, "not a number"},
      {kImuHeader + ok + "2.0,0,0,,0,0,9.8\n", 3, "not a number"},
      {kImuHeader + ok + "2.0,100,0,0,0,0,9.8\n", 3, "outside the physical range"},
      {kImuHeader + ok + "2.0,0,0,0,0,0,9800\n", 3, "outside the physical range"},
      {kImuHeader + "-5,0,0,0,0,0,9.8\n", 2, "outside the physical range"},
  };
  for (size_t i = 0; i < cases.size(); ++i) {
    const std::string path = dir.write("imu" + std::to_string(i) + ".csv", cases[i].content);
    expectDataError([&] { readImuCsv(path); }, path, cases[i].line, cases[i].what);
  }
  expectDataError([&] { readImuCsv(dir.file("missing.csv")); }, dir.file("missing.csv"), 0,
                  "cannot open");
}

// Recoverable damage (issue 23): a cut last line, a row with NaN or infinite values, a repeated
// time and a single sample out of order are dropped with one warning each naming the first line;
// more than 100 such rows in a row stop the read.
TEST(ImuCsv, RecoverableDamageIsDroppedWithAWarning) {
  test::TempDir dir;
  const std::string path = dir.write(
      "imu.csv", kImuHeader + "1.0,0,0,0,0,0,9.8\n2.0,nan,0,0,0,0,9.8\n3.0,0,inf,0,0,0,9.8\n" +
                     "4.0,0,0,0,0,0,9.8\n4.0,0,0,0,0,0,9.8\n5.0,0,0,0,0,0,9.8\n" +
                     "4.5,0,0,0,0,0,9.8\n6.0,0,0,0,0,0,9.8\n7.0,0,0,0.1");
  std::vector<std::string> warnings;
  const auto imu = readImuCsv(path, &warnings);
  ASSERT_EQ(imu.size(), 4u);  // 1, 4, 5, 6
  EXPECT_EQ(imu[3].t, 6.0);
  ASSERT_EQ(warnings.size(), 4u);
  EXPECT_EQ(warnings[0], path + ":3: 2 rows with NaN or infinite values dropped (first here)");
  EXPECT_EQ(warnings[1], path + ":6: 1 rows repeating the previous time dropped (first here)");
  EXPECT_EQ(warnings[2], path + ":8: 1 rows with time going backwards dropped (first here)");
  EXPECT_EQ(warnings[3], path + ":10: 1 last line cut short dropped (first here)");

  std::string burst = kImuHeader + "1.0,0,0,0,0,0,9.8\n";
  for (int k = 0; k < 101; ++k) burst += std::to_string(2 + k) + ",nan,0,0,0,0,9.8\n";
  const std::string broken = dir.write("burst.csv", burst);
  expectDataError([&] { readImuCsv(broken); }, broken, 103, "101 rows in a row with NaN");
}

// One odometer row stamped 1024 weeks late (a GPS week-rollover glitch) is one bad row, not the
// start of 100 rows going backwards: it is dropped, named by its line, and the rest is read.
TEST(OdomCsv, OneRowStampedFarAheadIsDroppedAsOneRow) {
  test::TempDir dir;
  std::string text = "t,v,w\n";
  for (int k = 0; k < 300; ++k) {
    const double t = 100.0 + 0.1 * k + (k == 150 ? 1024 * 604800.0 : 0.0);
    text += std::to_string(t) + ",1.0,0.0\n";
  }
  const std::string path = dir.write("odom.csv", text);
  std::vector<std::string> warnings;
  const auto odom = readOdomCsv(path, &warnings);
  ASSERT_EQ(odom.size(), 299u);
  for (size_t k = 1; k < odom.size(); ++k) EXPECT_LT(odom[k].t - odom[k - 1].t, 0.25);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], path +
                             ":152: 1 rows stamped far ahead of the rows before and after them "
                             "dropped (first here)");
  // The same jump where the rows after it go on from it is a gap, kept.
  std::string gap = "t,v,w\n";
  for (int k = 0; k < 300; ++k)
    gap += std::to_string(100.0 + 0.1 * k + (k >= 150 ? 50 : 0)) + ",1,0\n";
  warnings.clear();
  EXPECT_EQ(readOdomCsv(dir.write("gap.csv", gap), &warnings).size(), 300u);
  EXPECT_TRUE(warnings.empty());
}

TEST(ImuCsv, SkipsCommentsAndBlankLines) {
  test::TempDir dir;
  const std::string path =
      dir.write("imu.csv", "# recorded by a test\n" + kImuHeader + "\n1.0,0,0,0,0,0,9.8\r\n");
  EXPECT_EQ(readImuCsv(path).size(), 1u);
}

TEST(ImuCsv, NumbersAreReadAsStrtodReadsThem) {
  // The reader parses with std::from_chars (no locale, no copies); what strtod accepted stays
  // accepted, with the same values: signs, exponents, spaces around fields, and an overflow is
  // infinite (a damaged row), not an error.
  test::TempDir dir;
  const std::string path =
      dir.write("imu.csv", kImuHeader + " +1.0 , -0 ,.5,5.,1e-3,+2.5E+1, 9.8\n" +
                               "2.0,1e400,0,0,0,0,9.8\n3.0,0,0,0,0,0,0x10\n");
  std::vector<std::string> warnings;
  try {
    readImuCsv(path, &warnings);
    FAIL() << "hexadecimal accepted";
  } catch (const DataError& e) {
    EXPECT_EQ(e.line(), 4);  // strtod read "0x10" as 16; giocal's files are decimal
  }
  const std::string ok = dir.write("ok.csv", kImuHeader + " +1.0 , -0 ,.5,5.,1e-3,+2.5E+1, 9.8\n" +
                                                 "2.0,1e400,0,0,0,0,9.8\n3.0,0,0,0,0,0,9.80665\n");
  const auto imu = readImuCsv(ok, &warnings);
  ASSERT_EQ(imu.size(), 2u);
  EXPECT_EQ(imu[0].t, 1.0);
  EXPECT_EQ(imu[0].gyro, Eigen::Vector3d(-0.0, 0.5, 5.0));
  EXPECT_EQ(imu[0].acc, Eigen::Vector3d(1e-3, 25.0, 9.8));
  EXPECT_EQ(imu[1].acc.z(), std::strtod("9.80665", nullptr));
  ASSERT_EQ(warnings.size(), 1u);  // the overflow row
  EXPECT_NE(warnings[0].find(":3: 1 rows with NaN or infinite values"), std::string::npos);
  for (const char* bad : {"+-1", "1e", "--1", "1.0.0", "+"}) {
    const std::string f =
        dir.write("bad.csv", kImuHeader + "1.0,0,0," + std::string(bad) + ",0,0,9.8\n");
    expectDataError([&] { readImuCsv(f); }, f, 2, "not a number");
  }
}

TEST(OdomCsv, RoundTripAndBadInput) {
  test::TempDir dir;
  writeOdomCsv(dir.file("odom.csv"), {{10.0, 0.5, 0.1}, {10.04, 0.6, -0.1}});
  const auto back = readOdomCsv(dir.file("odom.csv"));
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[1].v, 0.6);
  EXPECT_EQ(back[1].w, -0.1);
  const std::string h = "t,v,w\n";
  const auto p1 = dir.write("a.csv", h + "1,0.1,0\n1,0.1,0\n");
  std::vector<std::string> warnings;
  EXPECT_EQ(readOdomCsv(p1, &warnings).size(), 1u);  // the repeated row dropped
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], p1 + ":3: 1 rows repeating the previous time dropped (first here)");
  const auto p2 = dir.write("b.csv", h + "1,70,0\n");
  expectDataError([&] { readOdomCsv(p2); }, p2, 2, "'v' value 70");
  const auto p3 = dir.write("c.csv", h + "1,0.1\n2,0.1,0\n");
  expectDataError([&] { readOdomCsv(p3); }, p3, 2, "expected 3 columns");
  const auto p4 = dir.write("d.csv", "t,v,yaw\n1,0.1,0\n");
  expectDataError([&] { readOdomCsv(p4); }, p4, 1, "header must be 't,v,w'");
}

TEST(TruthCsv, RoundTripAndBadInput) {
  test::TempDir dir;
  TruthSample s;
  s.t = 1e9;
  s.lat_deg = 35.1;
  s.lon_deg = 136.9;
  s.h = 50.0;
  s.v_enu = {1.0, -0.5, 0.01};
  s.q_n_b = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()));
  writeTruthCsv(dir.file("truth.csv"), {s});
  const auto back = readTruthCsv(dir.file("truth.csv"));
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0].lat_deg, 35.1);
  EXPECT_LT(back[0].q_n_b.angularDistance(s.q_n_b), 1e-12);
  const std::string h = "t,lat,lon,h,ve,vn,vu,qw,qx,qy,qz\n";
  const auto p1 = dir.write("a.csv", h + "1,95,0,0,0,0,0,1,0,0,0\n");
  expectDataError([&] { readTruthCsv(p1); }, p1, 2, "'lat' value 95");
  const auto p2 = dir.write("b.csv", h + "1,35,0,0,0,0,0,0.5,0,0,0\n");
  expectDataError([&] { readTruthCsv(p2); }, p2, 2, "not of unit norm");
}

}  // namespace
}  // namespace giocal
