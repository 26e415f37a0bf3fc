// RosSchema: a ROS message definition as a bag stores it with each connection (the type's .msg
// text followed by "MSG: pkg/Type" sections of the types it uses), parsed into fields so that
// serialized messages can be read by field name whatever the package.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace giocal::import {

struct RosField {
  std::string type;  // a primitive ("float64", "string", "time", ...) or a full type "pkg/Type"
  std::string name;
  int array = -1;  // -1: not an array; 0: variable length; n > 0: fixed length n
};

class RosSchema {
 public:
  /// Parses the definition of `root_type` ("pkg/Type"); throws std::runtime_error naming the type
  /// and the line for a field it cannot read or a type it cannot resolve.
  RosSchema(const std::string& root_type, const std::string& definition);

  const std::string& root() const { return root_; }
  /// The fields of a type of this schema (constants left out).
  const std::vector<RosField>& fieldsOf(const std::string& type) const;

 private:
  std::string root_;
  std::map<std::string, std::vector<RosField>> types_;
};

/// True for the primitive types of ROS message definitions (ROS 1 and ROS 2).
bool isRosPrimitive(const std::string& type);

/// The ROS 2 definition of a message type giocal reads (sensor_msgs/msg/Imu, nav_msgs/msg/Odometry,
/// geometry_msgs/msg/TwistStamped, sensor_msgs/msg/NavSatFix), for bags that store none (rosbag2
/// before Iron); empty for other types.
std::string builtinRos2Definition(const std::string& type);

}  // namespace giocal::import
