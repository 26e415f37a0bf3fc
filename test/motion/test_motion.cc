#include <gtest/gtest.h>

#include <random>

#include "common/motion/motion_detector.h"

namespace giocal {
namespace {

constexpr double kDeg = 0.017453292519943295;

TEST(MotionDetector, StaticNeedsAFullQuietWindow) {
  MotionDetector d;
  std::mt19937 rng(4);
  std::normal_distribution<double> noise(0.0, 0.005 * kDeg);  // bias-compensated MEMS noise
  EXPECT_FALSE(d.isStatic());
  for (int k = 0; k < 50; ++k)
    d.addImu(k * 0.01, Eigen::Vector3d(noise(rng), noise(rng), noise(rng)));
  EXPECT_FALSE(d.isStatic()) << "half a window is not enough";
  for (int k = 50; k < 101; ++k)
    d.addImu(k * 0.01, Eigen::Vector3d(noise(rng), noise(rng), noise(rng)));
  EXPECT_TRUE(d.isStatic());
  // A slow turn of 0.1 deg/s is motion.
  for (int k = 101; k < 250; ++k) d.addImu(k * 0.01, Eigen::Vector3d(0, 0, 0.1 * kDeg));
  EXPECT_FALSE(d.isStatic());
  EXPECT_NEAR(d.meanGyroNorm(), 0.1 * kDeg, 1e-12);
}

TEST(MotionDetector, NhcNeedsSpeedAndLittleRotation) {
  MotionDetectorOptions opt;
  MotionDetector d(opt);
  for (int k = 0; k <= 100; ++k) {
    d.addImu(k * 0.01, Eigen::Vector3d(0, 0, 2.0 * kDeg));
    if (k % 4 == 0) d.addOdometer(k * 0.01, 1.5);
  }
  EXPECT_TRUE(d.nhcApplies());
  EXPECT_FALSE(d.isStatic());
  // Turning at 10 deg/s: no NHC.
  for (int k = 101; k <= 300; ++k) d.addImu(k * 0.01, Eigen::Vector3d(0, 0, 10.0 * kDeg));
  for (int k = 101; k <= 300; k += 4) d.addOdometer(k * 0.01, 1.5);
  EXPECT_FALSE(d.nhcApplies());
  // Slow straight driving (the paper's simulation runs at 0.25 m/s): no NHC at the default
  // threshold, NHC with a lowered one.
  MotionDetectorOptions slow;
  slow.nhc_min_speed = 0.2;
  MotionDetector d1, d2(slow);
  for (int k = 0; k <= 100; ++k) {
    for (MotionDetector* m : {&d1, &d2}) {
      m->addImu(k * 0.01, Eigen::Vector3d::Zero());
      if (k % 4 == 0) m->addOdometer(k * 0.01, 0.25);
    }
  }
  EXPECT_FALSE(d1.nhcApplies());
  EXPECT_TRUE(d2.nhcApplies());
}

TEST(MotionDetector, TimeGoingBackwardsRestartsTheWindow) {
  MotionDetector d;
  for (int k = 0; k <= 100; ++k) d.addImu(k * 0.01, Eigen::Vector3d::Zero());
  EXPECT_TRUE(d.isStatic());
  d.addImu(0.5, Eigen::Vector3d::Zero());
  EXPECT_FALSE(d.isStatic());
}

}  // namespace
}  // namespace giocal
