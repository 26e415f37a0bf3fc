// Test support: ROS 1 bags written with Debian's rosbag_storage from RosMessages (serialized by
// giocal's codec), and the ROS 1 definitions of the message types giocal imports.
#pragma once

#include <ros/message_traits.h>
#include <ros/serialization.h>
#include <rosbag/bag.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "import/ros_message.h"
#include "import/ros_schema.h"

// A message written as serialized bytes with its type and definition (what rosbag stores).
struct RawRosMessage {
  std::string type, definition;
  std::vector<uint8_t> bytes;
};

namespace ros {
namespace message_traits {
template <>
struct IsMessage<RawRosMessage> : TrueType {};
template <>
struct MD5Sum<RawRosMessage> {
  static const char* value(const RawRosMessage&) { return "*"; }
  static const char* value() { return "*"; }
};
template <>
struct DataType<RawRosMessage> {
  static const char* value(const RawRosMessage& m) { return m.type.c_str(); }
  static const char* value() { return "*"; }
};
template <>
struct Definition<RawRosMessage> {
  static const char* value(const RawRosMessage& m) { return m.definition.c_str(); }
  static const char* value() { return ""; }
};
}  // namespace message_traits
namespace serialization {
template <>
struct Serializer<RawRosMessage> {
  template <typename Stream>
  static void write(Stream& stream, const RawRosMessage& m) {
    std::memcpy(stream.advance(static_cast<uint32_t>(m.bytes.size())), m.bytes.data(),
                m.bytes.size());
  }
  static uint32_t serializedLength(const RawRosMessage& m) {
    return static_cast<uint32_t>(m.bytes.size());
  }
};
}  // namespace serialization
}  // namespace ros

namespace giocal::import::test_bags {

// ROS 1 definitions of the message types (their .msg files as rosbag stores them).
const std::string kHeader = "MSG: std_msgs/Header\nuint32 seq\ntime stamp\nstring frame_id\n";
const std::string kVector3 = "MSG: geometry_msgs/Vector3\nfloat64 x\nfloat64 y\nfloat64 z\n";
const std::string kQuaternion =
    "MSG: geometry_msgs/Quaternion\nfloat64 x\nfloat64 y\nfloat64 z\nfloat64 w\n";
const std::string kImuDef =
    "Header header\ngeometry_msgs/Quaternion orientation\nfloat64[9] orientation_covariance\n"
    "geometry_msgs/Vector3 angular_velocity\nfloat64[9] angular_velocity_covariance\n"
    "geometry_msgs/Vector3 linear_acceleration\nfloat64[9] linear_acceleration_covariance\n" +
    kHeader + kQuaternion + kVector3;
const std::string kTwistDef = "MSG: geometry_msgs/Twist\nVector3 linear\nVector3 angular\n";
const std::string kOdomDef =
    "Header header\nstring child_frame_id\ngeometry_msgs/PoseWithCovariance pose\n"
    "geometry_msgs/TwistWithCovariance twist\n" +
    kHeader +
    "MSG: geometry_msgs/PoseWithCovariance\nPose pose\nfloat64[36] covariance\n"
    "MSG: geometry_msgs/Pose\nPoint position\nQuaternion orientation\n"
    "MSG: geometry_msgs/Point\nfloat64 x\nfloat64 y\nfloat64 z\n" +
    kQuaternion + "MSG: geometry_msgs/TwistWithCovariance\nTwist twist\nfloat64[36] covariance\n" +
    kTwistDef + kVector3;
const std::string kTwistStampedDef =
    "Header header\ngeometry_msgs/Twist twist\n" + kHeader + kTwistDef + kVector3;
const std::string kFixDef =
    "Header header\nsensor_msgs/NavSatStatus status\nfloat64 latitude\nfloat64 longitude\n"
    "float64 altitude\nfloat64[9] position_covariance\nuint8 position_covariance_type\n" +
    kHeader + "MSG: sensor_msgs/NavSatStatus\nint8 status\nuint16 service\n";

// Writes messages with their stamps ("header.stamp", when the type has a header) into a bag.
class BagWriter {
 public:
  explicit BagWriter(const std::string& path) { bag_.open(path, rosbag::bagmode::Write); }
  void write(const std::string& topic, const std::string& type, const std::string& def,
             RosMessage m, double stamp, double received) {
    m.set("header.stamp.sec", std::floor(stamp));
    m.set("header.stamp.nsec", std::round((stamp - std::floor(stamp)) * 1e9));
    const RosSchema schema(type, def);
    bag_.write(topic, ros::Time(received),
               RawRosMessage{type, def, m.encode(schema, RosEncoding::kRos1)});
  }

 private:
  rosbag::Bag bag_;
};

// A robot standing still beside the data under test: /imu (gravity only) and /odom (zero) at 10 Hz
// for `seconds` from t0 (seconds since 1970).
inline void writeStandingRobot(BagWriter& w, double t0, double seconds) {
  for (int k = 0; k < static_cast<int>(seconds * 10.0); ++k) {
    const double t = t0 + 0.1 * k;
    RosMessage imu;
    imu.set("linear_acceleration.z", 9.8);
    w.write("/imu", "sensor_msgs/Imu", kImuDef, imu, t, t);
    w.write("/odom", "nav_msgs/Odometry", kOdomDef, RosMessage{}, t, t);
  }
}

}  // namespace giocal::import::test_bags
