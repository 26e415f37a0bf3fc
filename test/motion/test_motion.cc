#include <gtest/gtest.h>

#include <random>

#include "common/motion/motion_detector.h"

namespace giocal {
namespace {

constexpr double kDeg = 0.017453292519943295;
const Eigen::Vector3d kStill(0.0, 0.0, 9.8);  // the specific force of an IMU at rest

TEST(MotionDetector, StaticNeedsAFullQuietWindow) {
  MotionDetector d;
  std::mt19937 rng(4);
  std::normal_distribution<double> noise(0.0, 0.005 * kDeg);  // bias-compensated MEMS noise
  EXPECT_FALSE(d.isStatic());
  for (int k = 0; k < 50; ++k)
    d.addImu(k * 0.01, Eigen::Vector3d(noise(rng), noise(rng), noise(rng)), kStill);
  EXPECT_FALSE(d.isStatic()) << "half a window is not enough";
  for (int k = 50; k < 101; ++k)
    d.addImu(k * 0.01, Eigen::Vector3d(noise(rng), noise(rng), noise(rng)), kStill);
  EXPECT_TRUE(d.isStatic());
  // A slow turn of 0.1 deg/s is motion.
  for (int k = 101; k < 250; ++k) d.addImu(k * 0.01, Eigen::Vector3d(0, 0, 0.1 * kDeg), kStill);
  EXPECT_FALSE(d.isStatic());
  EXPECT_NEAR(d.meanGyroNorm(), 0.1 * kDeg, 1e-12);
}

TEST(MotionDetector, NhcNeedsSpeedAndLittleRotation) {
  MotionDetectorOptions opt;
  MotionDetector d(opt);
  for (int k = 0; k <= 100; ++k) {
    d.addImu(k * 0.01, Eigen::Vector3d(0, 0, 2.0 * kDeg), kStill);
    if (k % 4 == 0) d.addOdometer(k * 0.01, 1.5);
  }
  EXPECT_TRUE(d.nhcApplies());
  EXPECT_FALSE(d.isStatic());
  // Turning at 10 deg/s: no NHC.
  for (int k = 101; k <= 300; ++k) d.addImu(k * 0.01, Eigen::Vector3d(0, 0, 10.0 * kDeg), kStill);
  for (int k = 101; k <= 300; k += 4) d.addOdometer(k * 0.01, 1.5);
  EXPECT_FALSE(d.nhcApplies());
  // Slow straight driving (the paper's simulation runs at 0.25 m/s): no NHC at the default
  // threshold, NHC with a lowered one.
  MotionDetectorOptions slow;
  slow.nhc_min_speed = 0.2;
  MotionDetector d1, d2(slow);
  for (int k = 0; k <= 100; ++k) {
    for (MotionDetector* m : {&d1, &d2}) {
      m->addImu(k * 0.01, Eigen::Vector3d::Zero(), kStill);
      if (k % 4 == 0) m->addOdometer(k * 0.01, 0.25);
    }
  }
  EXPECT_FALSE(d1.nhcApplies());
  EXPECT_TRUE(d2.nhcApplies());
}

// A straight start from rest: no rotation, and the wheels' one-second mean still under its
// threshold for the first 0.2 s, but the accelerometer shows it at once.
TEST(MotionDetector, AStraightStartIsMotionBeforeTheWheelsShowIt) {
  MotionDetectorOptions opt;
  opt.accel_noise_density = 6e-4;  // 60 ug/sqrt(Hz), the field preset's
  MotionDetector d(opt);
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0.0, opt.accel_noise_density * std::sqrt(400.0));
  const auto force = [&](double a_x) {
    return Eigen::Vector3d(a_x + noise(rng), noise(rng), 9.8 + noise(rng));
  };
  int static_samples = 0;
  for (int k = 0; k < 400; ++k) {  // 1 s at rest, 400 Hz
    d.addImu(k / 400.0, Eigen::Vector3d::Zero(), force(0.0));
    static_samples += d.isStatic() ? 1 : 0;
  }
  EXPECT_GT(static_samples, 0);
  for (int k = 0; k <= 40; ++k) d.addImu(1.0 + k / 400.0, Eigen::Vector3d::Zero(), force(0.0));
  EXPECT_TRUE(d.isStatic());
  d.addOdometer(1.1, 0.0);
  // 0.05 s at 0.3 m/s^2: 1.5 cm/s, the wheels' mean over the window still under 1 cm/s.
  for (int k = 1; k <= 20; ++k) d.addImu(1.1 + k / 400.0, Eigen::Vector3d::Zero(), force(0.3));
  d.addOdometer(1.15, 0.015);
  EXPECT_LT(std::abs(d.meanSpeed()), opt.zupt_max_speed);
  EXPECT_LT(d.meanGyroNorm(), d.staticGyroThreshold());
  EXPECT_FALSE(d.accelSteady());
  EXPECT_FALSE(d.isStatic());
}

TEST(MotionDetector, TimeGoingBackwardsRestartsTheWindow) {
  MotionDetector d;
  for (int k = 0; k <= 100; ++k) d.addImu(k * 0.01, Eigen::Vector3d::Zero(), kStill);
  EXPECT_TRUE(d.isStatic());
  d.addImu(0.5, Eigen::Vector3d::Zero(), kStill);
  EXPECT_FALSE(d.isStatic());
}

}  // namespace
}  // namespace giocal
