// The LC solutions' heights against the height profile the IMU's grade and the odometer give.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "common/calibration/fix_heights.h"
#include "common/geodesy/wgs84.h"
#include "common/math/rotation.h"

namespace giocal {
namespace {

constexpr double kG = 9.81;

struct Drive {
  double grade = 0.0;        // sin of the road's grade
  double wander_m = 0.0;     // amplitude of the heights' slow error
  double noise_m = 1.6;      // the heights' white error, as stated
  double mount_pitch = 0.0;  // an error in the mounting's pitch the guess does not know [rad]
  double seconds = 300.0;
};

// A straight drive at 1.2 m/s: IMU at 100 Hz, odometer at 10 Hz, fixes at 1 Hz stating 1.6 m.
FixHeights check(const Drive& d, unsigned seed = 1) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n01(0.0, 1.0);
  const Eigen::Matrix3d R_b_m = rotationFromRpy({-1.5707963, 0.0, 0.0});  // the IMU on its side
  const Eigen::Matrix3d R_b_m_true = R_b_m * rotationFromRpy({0.0, d.mount_pitch, 0.0});
  DriveProfile drive(R_b_m);
  const double v = 1.2, theta = std::asin(d.grade);
  for (int k = 0; k <= static_cast<int>(d.seconds * 100); ++k) {
    ImuSample s;
    s.t = 1000.0 + k * 0.01;
    const Eigen::Vector3d f_m(kG * std::sin(theta), 0.0, kG * std::cos(theta));
    s.acc = R_b_m_true * f_m + 0.02 * Eigen::Vector3d(n01(rng), n01(rng), n01(rng));
    s.gyro.setZero();
    drive.addImu(s);
    if (k % 10 == 0) drive.addOdometer({s.t, v + 0.01 * n01(rng), 0.0});
  }
  std::vector<PositionFix> fixes;
  for (int k = 1; k < static_cast<int>(d.seconds); ++k) {
    const double t = static_cast<double>(k);
    Geodetic g{0.74, -1.24, 20.0 + v * t * d.grade};
    g.h += d.wander_m * std::sin(2.0 * M_PI * t / 180.0) + d.noise_m * n01(rng);
    PositionFix f;
    f.t = 1000.0 + t;
    f.p_e = ecefFromGeodetic(g);
    f.cov_enu = Eigen::Vector3d(0.8 * 0.8, 0.8 * 0.8, 1.6 * 1.6).asDiagonal();
    fixes.push_back(f);
  }
  return checkFixHeights(fixes, drive);
}

TEST(FixHeights, HeightsAsGoodAsTheirSigmaGiveAScaleNearOne) {
  const FixHeights r = check({});
  ASSERT_TRUE(r.decided) << r.why_not;
  EXPECT_NEAR(r.reported_sigma_m, 1.6, 1e-9);
  EXPECT_NEAR(r.scale(), 1.0, 0.25);
  EXPECT_NEAR(r.distance_m, 1.2 * 298, 5.0);
}

TEST(FixHeights, HeightsThatWanderByMetresGiveTheirSpread) {
  Drive d;
  d.wander_m = 10.0;  // a sine of 10 m: 7 m RMS, about 8 m robust sigma with the noise
  const FixHeights r = check(d);
  ASSERT_TRUE(r.decided);
  EXPECT_GT(r.scale(), 3.5);
  EXPECT_LT(r.scale(), 6.5);
}

TEST(FixHeights, AHillTheImuSeesIsNotAnError) {
  Drive d;
  d.grade = 0.08;  // 29 m of climb over the drive
  const FixHeights r = check(d, 2);
  ASSERT_TRUE(r.decided);
  EXPECT_NEAR(r.scale(), 1.0, 0.25);
  EXPECT_NEAR(r.grade, 0.0, 0.005);  // the IMU explained it
}

TEST(FixHeights, AMountingPitchErrorIsFittedAsAGrade) {
  Drive d;
  d.grade = 0.05;
  d.mount_pitch = 2.0 * M_PI / 180.0;  // the profile leans by 2 degrees
  const FixHeights r = check(d, 3);
  ASSERT_TRUE(r.decided);
  EXPECT_NEAR(r.scale(), 1.0, 0.25);
  EXPECT_NEAR(std::abs(r.grade), std::sin(2.0 * M_PI / 180.0), 0.005);
}

TEST(FixHeights, AShortDriveIsNotDecidedAndSaysWhy) {
  Drive d;
  d.seconds = 20.0;
  const FixHeights r = check(d);
  EXPECT_FALSE(r.decided);
  EXPECT_NE(r.why_not.find("19 fixes"), std::string::npos) << r.why_not;
}

TEST(FixHeights, AStampDaysAheadDoesNotGrowTheProfile) {
  DriveProfile drive(Eigen::Matrix3d::Identity());
  drive.addImu({10.0, Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, kG)});
  drive.addOdometer({10.01, 1.0, 0.0});
  drive.addImu({10.0 + 1024 * 7 * 86400.0, Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, kG)});
  drive.addOdometer({9.0, 1.0, 0.0});  // before the first bin: not part of the drive
  EXPECT_EQ(drive.finished().size(), 1u);
}

}  // namespace
}  // namespace giocal
