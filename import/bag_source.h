// BagSource: the topics of a recorded bag and their serialized messages in time order, from a ROS 1
// bag (Debian's rosbag_storage library) or a rosbag2 sqlite3 database (Debian's sqlite3).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "import/ros_message.h"

namespace giocal::import {

struct BagTopic {
  std::string topic;
  std::string type;        // "sensor_msgs/Imu" (ROS 1) or "sensor_msgs/msg/Imu" (ROS 2)
  std::string definition;  // the message definition the bag stores; ROS 2: empty before Iron
  long long messages = 0;
};

class BagSource {
 public:
  virtual ~BagSource() = default;
  virtual const std::string& path() const = 0;
  virtual RosEncoding encoding() const = 0;
  virtual const std::vector<BagTopic>& topics() const = 0;
  /// Calls `fn` with every message of the given topics in recording order (the bag's receive
  /// time, seconds since 1970); throws std::runtime_error naming the bag when it cannot be read.
  using Visit = std::function<void(const BagTopic&, double t, const uint8_t* data, std::size_t)>;
  virtual void read(const std::set<std::string>& topics, const Visit& fn) const = 0;
};

/// Opens a ROS 1 bag (.bag); throws std::runtime_error naming the file when it is not one.
std::unique_ptr<BagSource> openRos1Bag(const std::string& path);

/// Opens a rosbag2 sqlite3 database (a .db3 file, or the bag folder holding one); throws
/// std::runtime_error naming the file when it is not one.
std::unique_ptr<BagSource> openRos2Bag(const std::string& path);

/// A ROS 1 bag file, or a rosbag2 folder (metadata.yaml and .db3) or .db3 file.
std::unique_ptr<BagSource> openBag(const std::string& path);

}  // namespace giocal::import
