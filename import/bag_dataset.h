// BagDataset: the IMU, wheel odometry and GNSS fixes of a ROS bag as giocal's sensor logs, with
// the sensor noise its message covariances give, in GPS time, and every sample it had to drop.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "common/gnss/rtk.h"
#include "common/imu/imu_sample.h"
#include "common/io/dataset_description.h"
#include "common/odometer/odom_sample.h"
#include "import/bag_source.h"
#include "import/bag_stamps.h"
#include "import/ubx_log.h"

namespace giocal::import {

/// Topics to read; empty: the one topic of the type (sensor_msgs/Imu; nav_msgs/Odometry or
/// geometry_msgs/TwistStamped; sensor_msgs/NavSatFix), an error when several are present. Raw GNSS
/// (ublox_msgs/RxmRAWX and RxmSFRBX, or gnss_comm/GnssMeasMsg and GnssEphemMsg) is read from the
/// one topic of each type.
struct BagTopics {
  std::string imu, odom, fix;
  StampSource stamps = StampSource::kAuto;  // header stamps or record times (bag_stamps.h)
};

struct TopicCounts {
  std::string topic, type;
  long long read = 0;
  long long out_of_order = 0;  // stamps not after the previous one (dropped)
  bool record_times = false;   // the bag's record times replaced the header stamps
  long long non_finite = 0;    // NaN or infinite values (dropped)
  long long no_fix = 0;        // NavSatFix with status -1 (dropped)
  double largest_gap_s = 0.0;
};

struct BagDataset {
  std::vector<ImuSample> imu;
  std::vector<OdomSample> odom;
  std::vector<RtkSolution> fixes;  // NavSatFix positions: quality 5 single, 4 DGPS/GBAS, 3 SBAS
  // Raw GNSS of ublox_msgs/RxmRAWX (with RxmSFRBX for ephemerides) or gnss_comm/GnssMeasMsg
  // (with GnssEphemMsg), when the bag has them.
  std::optional<UbxLog> raw_gnss;
  std::string raw_gnss_source;  // "ublox_msgs" or "gnss_comm"
  std::string raw_observation_topic, raw_ephemeris_topic;
  TopicCounts imu_counts, odom_counts, fix_counts;
  ImuNoise imu_noise;  // from the message covariances where meaningful, else the defaults
  OdometerNoise odom_noise;
  std::vector<std::string> noise_sources;  // one line per value: "covariance" or "default"
  std::string imu_accel_unit = "m/s^2";    // the unit the bag's accelerations were in (converted)
  bool utc_stamps = true;  // false: stamps are not UTC (simulated or relative ROS time), kept as is
  int leap_seconds = 0;    // GPS - UTC applied
  std::vector<std::string> warnings;
};

/// Reads the bag; throws std::runtime_error naming the bag and the topic or type for a bag without
/// an IMU or odometry topic, ambiguous or unknown topics, messages that do not decode, sensors
/// whose stamps are not on one time base, and an IMU whose mean specific force is gravity in no
/// unit. Accelerations in g or mg are converted to m/s^2 (imu_accel_unit, a warning). `progress`
/// (may be empty) is called with the share of the messages read (it may throw to stop).
BagDataset readBagDataset(const BagSource& bag, const BagTopics& topics,
                          const std::function<void(double)>& progress = {});

}  // namespace giocal::import
