// `giocal import --bag`: ROS 1 bags written here with Debian's rosbag_storage (every message type,
// simulated values, round trip) and the real Husky and Jackal bags; bad bags answer with the topic.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "common/geodesy/wgs84.h"
#include "common/time/gps_time.h"
#include "import/bag_dataset.h"
#include "import/bag_source.h"
#include "import/ros1_bag_writer.h"
#include "import/ros_schema.h"
#include "temp_dir.h"

namespace giocal::import {
namespace {

using namespace test_bags;

const std::string kReal = std::string(GIOCAL_SOURCE_DIR) + "/data/real/husky-robot-localization/";

constexpr double kT0 = 1700000000.0;  // 2023-11-14 22:13:20 UTC; GPS - UTC = 18 s

RosMessage imuMessage(double k) {
  RosMessage m;
  m.set("angular_velocity.x", 0.01 * k);
  m.set("angular_velocity.y", -0.02);
  m.set("angular_velocity.z", 0.3);
  m.set("linear_acceleration.x", 0.1);
  m.set("linear_acceleration.y", 0.2 * (static_cast<int>(k) % 10));  // gravity stays the mean
  m.set("linear_acceleration.z", 9.81);
  for (int i : {0, 4, 8}) {
    m.set("angular_velocity_covariance[" + std::to_string(i) + "]", 1e-4);  // 0.01 rad/s at 100 Hz
    m.set("linear_acceleration_covariance[" + std::to_string(i) + "]", 4e-2);
  }
  return m;
}

// 10 s of IMU (100 Hz), odometry (20 Hz; Odometry or TwistStamped) and fixes (1 Hz).
void writeSimulatedBag(const std::string& path, bool twist_stamped, double odom_stamp_offset = 0) {
  BagWriter w(path);
  for (int k = 0; k < 1000; ++k) {
    const double t = kT0 + 0.01 * k;
    w.write("/imu", "sensor_msgs/Imu", kImuDef, imuMessage(k), t, t + 0.002);
    if (k % 5 == 0) {
      RosMessage m;
      const std::string twist = twist_stamped ? "twist" : "twist.twist";
      m.set(twist + ".linear.x", 1.0 + 0.001 * k);
      m.set(twist + ".angular.z", -0.1);
      m.set("twist.covariance[0]", 1e-4);
      m.set("twist.covariance[35]", 4e-4);
      w.write("/odom", twist_stamped ? "geometry_msgs/TwistStamped" : "nav_msgs/Odometry",
              twist_stamped ? kTwistStampedDef : kOdomDef, m, t + odom_stamp_offset, t + 0.003);
    }
    if (k % 100 == 0) {
      RosMessage m;
      m.set("status.status", k == 500 ? -1 : 1);
      m.set("latitude", 42.375812 + 1e-6 * k);
      m.set("longitude", -71.147394);
      m.set("altitude", 7.3);
      for (int i : {0, 4}) m.set("position_covariance[" + std::to_string(i) + "]", 0.64);
      m.set("position_covariance[8]", 2.56);
      m.set("position_covariance_type", 2);
      w.write("/fix", "sensor_msgs/NavSatFix", kFixDef, m, t, t + 0.01);
    }
  }
}

TEST(BagImport, SimulatedBagsRoundTripEveryMessageType) {
  for (bool twist_stamped : {false, true}) {
    test::TempDir dir;
    writeSimulatedBag(dir.file("sim.bag"), twist_stamped);
    const BagDataset d = readBagDataset(*openBag(dir.file("sim.bag")), {});
    ASSERT_EQ(d.imu.size(), 1000u);
    ASSERT_EQ(d.odom.size(), 200u);
    ASSERT_EQ(d.fixes.size(), 9u);  // the NO_FIX one dropped
    EXPECT_EQ(d.fix_counts.no_fix, 1);
    EXPECT_TRUE(d.utc_stamps);
    EXPECT_EQ(d.leap_seconds, 18);
    EXPECT_NEAR(d.imu[3].t, kT0 - 315964800.0 + 18.0 + 0.03, 1e-6);
    EXPECT_DOUBLE_EQ(d.imu[3].gyro.x(), 0.03);
    EXPECT_DOUBLE_EQ(d.imu[7].acc.y(), 1.4);
    EXPECT_DOUBLE_EQ(d.odom[10].v, 1.05);
    EXPECT_DOUBLE_EQ(d.odom[10].w, -0.1);
    EXPECT_EQ(d.fixes[0].quality, 3);  // SBAS
    const Geodetic g = geodeticFromEcef(d.fixes[1].p_e);
    EXPECT_NEAR(g.lat * 180.0 / M_PI, 42.375912, 1e-9);
    const Eigen::Matrix3d R = rotationEcefFromEnu(g.lat, g.lon);
    const Eigen::Matrix3d cov_enu = R.transpose() * d.fixes[1].cov_e * R;
    EXPECT_NEAR(cov_enu(2, 2), 2.56, 1e-9);
    // sqrt(1e-4 * 0.01) and sqrt(4e-2 * 0.01); the sample interval from stamps near 1.4e9 s.
    EXPECT_NEAR(d.imu_noise.gyro_noise_density, 0.001, 1e-6);
    EXPECT_NEAR(d.imu_noise.accel_noise_density, 0.02, 1e-6);
    if (twist_stamped) {
      EXPECT_DOUBLE_EQ(d.odom_noise.speed_sigma, OdometerNoise{}.speed_sigma);  // no covariance
    } else {
      EXPECT_NEAR(d.odom_noise.speed_sigma, 0.01, 1e-12);
      EXPECT_NEAR(d.odom_noise.yaw_rate_sigma, 0.02, 1e-12);
    }
    // The NO_FIX fix dropped, and the gap of 2 s between usable fixes it leaves.
    ASSERT_EQ(d.warnings.size(), 2u) << d.warnings.back();
    EXPECT_NE(d.warnings[1].find("topic /fix: a gap of 2.00 s"), std::string::npos);
    EXPECT_NE(d.warnings[0].find("topic /fix: 1 fixes with status NO_FIX dropped"),
              std::string::npos);
  }
}

TEST(BagImport, BadBagsAnswerWithTheTopicAndTheProblem) {
  test::TempDir dir;
  auto error = [&](const std::string& bag, const BagTopics& topics = {}) {
    try {
      readBagDataset(*openBag(bag), topics);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  {  // no IMU topic
    BagWriter w(dir.file("no_imu.bag"));
    w.write("/odom", "nav_msgs/Odometry", kOdomDef, RosMessage{}, kT0, kT0);
  }
  EXPECT_NE(error(dir.file("no_imu.bag"))
                .find("no sensor_msgs/Imu topic (topics: /odom (nav_msgs/Odometry))"),
            std::string::npos)
      << error(dir.file("no_imu.bag"));
  {  // two IMU topics, and odometry on a clock of its own
    BagWriter w(dir.file("two.bag"));
    for (int k = 0; k < 10; ++k) {
      const double t = kT0 + 0.1 * k;
      w.write("/imu_a", "sensor_msgs/Imu", kImuDef, imuMessage(k), t, t);
      w.write("/imu_b", "sensor_msgs/Imu", kImuDef, imuMessage(k), t, t);
      w.write("/odom", "nav_msgs/Odometry", kOdomDef, RosMessage{}, 50.0 + 0.1 * k, t);
    }
  }
  EXPECT_NE(error(dir.file("two.bag"))
                .find("several sensor_msgs/Imu topics: /imu_a /imu_b; choose one with --imu-topic"),
            std::string::npos);
  BagTopics header_stamps{"/imu_a", "", "", StampSource::kHeader};
  EXPECT_NE(
      error(dir.file("two.bag"), header_stamps)
          .find("mixed time bases: stamps of /imu_a are wall-clock time, those of /odom are not"),
      std::string::npos)
      << error(dir.file("two.bag"), {"/imu_a", "", ""});
  EXPECT_NE(error(dir.file("two.bag"), {"/odom", "", ""})
                .find("topic /odom is nav_msgs/Odometry, not sensor_msgs/Imu"),
            std::string::npos);
  EXPECT_NE(error(dir.file("two.bag"), {"/nothere", "", ""}).find("no topic /nothere"),
            std::string::npos);
  EXPECT_NE(error(dir.file("missing.bag")).find("missing.bag: not a readable ROS 1 bag"),
            std::string::npos);
  const std::string text = dir.write("text.bag", "#ROSBAG V2.0\ngarbage");
  EXPECT_NE(error(text).find("text.bag"), std::string::npos) << error(text);

  // Odometry stamped 1.5 s late against its recording time, a repeated IMU sample and a NaN one:
  // read, with one warning each.
  writeSimulatedBag(dir.file("late.bag"), false, 1.5);
  {
    BagWriter w(dir.file("dup.bag"));
    for (int k = 0; k < 100; ++k) {
      const double t = kT0 + 0.01 * (k == 50 ? 49 : k);
      RosMessage m = imuMessage(k);
      if (k == 70) m.set("angular_velocity.y", NAN);
      w.write("/imu", "sensor_msgs/Imu", kImuDef, m, t, t);
      if (k % 5 == 0) w.write("/odom", "nav_msgs/Odometry", kOdomDef, RosMessage{}, t, t);
    }
  }
  const BagDataset late = readBagDataset(*openBag(dir.file("late.bag")), {});
  ASSERT_EQ(late.warnings.size(), 3u) << late.warnings.back();  // and the NO_FIX fix, its gap
  EXPECT_NE(late.warnings[0].find("differ by more than 1 s between sensors: /fix -0.010 s; /imu "
                                  "-0.002 s; /odom 1.497 s;"),
            std::string::npos)
      << late.warnings[0];
  const BagDataset dup = readBagDataset(*openBag(dir.file("dup.bag")), {});
  EXPECT_EQ(dup.imu.size(), 98u);
  EXPECT_EQ(dup.imu_counts.out_of_order, 1);
  EXPECT_EQ(dup.imu_counts.non_finite, 1);
  EXPECT_EQ(dup.warnings.size(), 2u);
}

// A bag whose odometry header stamps are frozen (every message the same stamp) while the bag's
// record times are good: the record times stand in, with a warning naming the topic; with
// --stamps header the old refusal; with --stamps record every topic takes its record times.
TEST(BagImport, FrozenHeaderStampsGiveWayToTheRecordTimes) {
  test::TempDir dir;
  {
    BagWriter w(dir.file("frozen.bag"));
    for (int k = 0; k < 1000; ++k) {
      const double t = kT0 + 0.01 * k;
      w.write("/imu", "sensor_msgs/Imu", kImuDef, imuMessage(k), t, t + 0.002);
      if (k % 5 == 0) {
        RosMessage m;
        m.set("twist.twist.linear.x", 1.0);
        w.write("/odom", "nav_msgs/Odometry", kOdomDef, m, kT0, t + 0.003);
      }
    }
  }
  const BagDataset d = readBagDataset(*openBag(dir.file("frozen.bag")), {});
  ASSERT_EQ(d.odom.size(), 200u);
  EXPECT_NEAR(d.odom[10].t - d.odom[9].t, 0.05, 1e-6);
  EXPECT_TRUE(d.odom_counts.record_times);
  EXPECT_FALSE(d.imu_counts.record_times);
  ASSERT_EQ(d.warnings.size(), 1u);
  EXPECT_NE(d.warnings[0].find("topic /odom: 199 of 200 header stamps not after the previous one"),
            std::string::npos)
      << d.warnings[0];
  BagTopics header;
  header.stamps = StampSource::kHeader;
  EXPECT_THROW(readBagDataset(*openBag(dir.file("frozen.bag")), header), std::runtime_error);
  BagTopics record;
  record.stamps = StampSource::kRecord;
  const BagDataset r = readBagDataset(*openBag(dir.file("frozen.bag")), record);
  EXPECT_TRUE(r.imu_counts.record_times);
  EXPECT_EQ(r.imu.size(), 1000u);
  EXPECT_THROW(stampSourceFromName("receive"), std::invalid_argument);
}

// sensor_msgs/Imu is m/s^2, but drivers publish g (a real Husky: mean |f| 1.03) and mg: converted
// and said; a force that is gravity in no unit names the topic.
TEST(BagImport, AccelerationsInGOrMgAreConvertedAndOtherUnitsRefused) {
  test::TempDir dir;
  for (const double unit : {1.0 / 9.80665, 1000.0 / 9.80665, 0.5}) {
    const std::string path = dir.file("unit.bag");
    {
      BagWriter w(path);
      for (int k = 0; k < 200; ++k) {
        const double t = kT0 + 0.01 * k;
        RosMessage m = imuMessage(k);
        m.set("linear_acceleration.x", 0.1 * unit);
        m.set("linear_acceleration.y", 0.0);
        m.set("linear_acceleration.z", 9.81 * unit);
        w.write("/imu", "sensor_msgs/Imu", kImuDef, m, t, t);
        if (k % 5 == 0) w.write("/odom", "nav_msgs/Odometry", kOdomDef, RosMessage{}, t, t);
      }
    }
    if (unit == 0.5) {
      try {
        readBagDataset(*openBag(path), {});
        ADD_FAILURE() << "a force of 4.9 m/s^2 was read";
      } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("topic /imu: the mean specific force is 4.905"),
                  std::string::npos)
            << e.what();
      }
      continue;
    }
    const BagDataset d = readBagDataset(*openBag(path), {});
    EXPECT_EQ(d.imu_accel_unit, unit < 1.0 ? "g" : "mg");
    EXPECT_NEAR(d.imu[7].acc.z(), 9.81, 1e-9);
    ASSERT_EQ(d.warnings.size(), 1u);
    EXPECT_NE(d.warnings[0].find("linear_acceleration in " + d.imu_accel_unit), std::string::npos);
  }
}

TEST(BagImport, RealHuskyAndJackalBags) {
  const BagDataset husky = readBagDataset(*openBag(kReal + "test1.bag"), {});
  EXPECT_EQ(husky.imu.size(), 11865u);  // SOURCE.txt's counts
  EXPECT_EQ(husky.odom.size(), 3952u);
  EXPECT_EQ(husky.fixes.size(), 989u);
  EXPECT_EQ(husky.leap_seconds, 16);  // May 2015
  // The first fix, 2015-05-21 19:11:38.039 UTC, is 19:11:54.039 GPS time.
  const CalendarTime c = calendarFromGpsSeconds(husky.fixes.front().t);
  EXPECT_EQ(c.hour * 3600 + c.minute * 60, 19 * 3600 + 11 * 60);
  EXPECT_NEAR(c.second, 54.039, 1e-3);
  // The IMU is mounted about 90 degrees off: gravity reads on +y.
  Eigen::Vector3d mean_acc = Eigen::Vector3d::Zero();
  for (const auto& s : husky.imu) mean_acc += s.acc / static_cast<double>(husky.imu.size());
  EXPECT_GT(mean_acc.y(), 9.5);
  EXPECT_LT(std::abs(mean_acc.x()) + std::abs(mean_acc.z()), 1.0);
  double speed = 0;
  for (const auto& s : husky.odom) speed += s.v / static_cast<double>(husky.odom.size());
  EXPECT_NEAR(speed, 0.9, 0.1);
  EXPECT_TRUE(husky.warnings.empty());
  EXPECT_EQ(husky.imu_accel_unit, "m/s^2");

  const BagDataset jackal = readBagDataset(*openBag(kReal + "test2.bag"), {});
  EXPECT_EQ(jackal.imu.size(), 3061u);
  EXPECT_EQ(jackal.odom.size(), 3060u);
  EXPECT_TRUE(jackal.fixes.empty());
  EXPECT_FALSE(jackal.utc_stamps);
  ASSERT_EQ(jackal.warnings.size(), 1u);
  EXPECT_NE(jackal.warnings[0].find("not wall-clock time"), std::string::npos);
}

}  // namespace
}  // namespace giocal::import
