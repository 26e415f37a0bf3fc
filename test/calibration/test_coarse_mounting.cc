// The mounting found from the data: simulated drives with the IMU mounted far from the vehicle
// axes (as the Husky's, about 90 degrees off) give R_b_m within the sigma they claim; the real
// Husky's log gives an up axis along its +y and a gyro that turns with its odometer.
#include <gtest/gtest.h>

#include <iostream>

#include "common/calibration/coarse_mounting.h"
#include "common/math/rotation.h"
#include "import/bag_dataset.h"
#include "import/bag_source.h"
#include "sim/simulator.h"

namespace giocal {
namespace {

double angleBetween(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  return a.angularDistance(b);
}

TEST(CoarseMounting, SimulatedDrivesWithTheImuFarOff) {
  for (const std::string preset : {"paper", "field"}) {
    for (const Eigen::Vector3d& rpy_deg :
         {Eigen::Vector3d(90, 0, 30), Eigen::Vector3d(-2, 3, 170), Eigen::Vector3d(180, 5, -60)}) {
      sim::SimConfig cfg =
          sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/" + preset + ".yaml");
      cfg.truth.q_b_m = Eigen::Quaterniond(rotationFromRpy(rpy_deg * kDegToRad));
      cfg.gnss.enabled = false;  // only the IMU and the odometer are used
      const sim::SimulatedLogs logs = sim::simulate(cfg, 3);
      const CoarseMounting m = estimateMounting(logs.imu, logs.odom);
      ASSERT_TRUE(m.valid) << preset << ": " << m.why_not;
      const double err = angleBetween(m.q_b_m, cfg.truth.q_b_m);
      std::cout << preset << " rpy_b_m [" << rpy_deg.transpose() << "] deg: found within "
                << err * kRadToDeg << " deg (sigma " << (m.sigma_rpy * kRadToDeg).transpose()
                << "), yaw rate slope " << m.yaw_rate_slope << "\n";
      EXPECT_LT(err, 3.0 * m.sigma_rpy.norm()) << preset;
      EXPECT_NEAR(m.yaw_rate_slope, 1.0 + cfg.truth.s_w, 0.1);  // gyro = (1 + s_w) w_measured
    }
  }
}

TEST(CoarseMounting, NothingToFindWithoutMotion) {
  std::vector<ImuSample> imu;
  std::vector<OdomSample> odom;
  for (int k = 0; k < 1000; ++k) {
    imu.push_back({0.01 * k, Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 9.8, 0)});
    if (k % 10 == 0) odom.push_back({0.01 * k, 0.0, 0.0});
  }
  const CoarseMounting m = estimateMounting(imu, odom);
  EXPECT_FALSE(m.valid);
  EXPECT_NE(m.why_not.find("no speed change or turn"), std::string::npos) << m.why_not;
}

TEST(CoarseMounting, RealHuskyLog) {
  if (!GIOCAL_ROS1_BAGS) GTEST_SKIP() << "built without ROS 1 bags (the 64-bit ARM build)";
  const auto bag = import::openBag(std::string(GIOCAL_SOURCE_DIR) +
                                   "/data/real/husky-robot-localization/test1.bag");
  const import::BagDataset d = import::readBagDataset(*bag, {});
  const CoarseMounting m = estimateMounting(d.imu, d.odom);
  ASSERT_TRUE(m.valid) << m.why_not;
  const Eigen::Matrix3d R_b_m = m.q_b_m.toRotationMatrix();
  std::cout << "Husky: R_b_m rpy " << (rpyFromRotation(R_b_m) * kRadToDeg).transpose()
            << " deg, sigma " << (m.sigma_rpy * kRadToDeg).transpose() << " deg; forward axis in b "
            << R_b_m.col(1).transpose() << ", yaw rate slope " << m.yaw_rate_slope << "\n";
  EXPECT_GT(R_b_m.col(2).y(), 0.99);  // up is the IMU's +y
  EXPECT_NEAR(m.yaw_rate_slope, 1.0, 0.3);
}

}  // namespace
}  // namespace giocal
