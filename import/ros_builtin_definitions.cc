// The ROS 2 message definitions (common_interfaces, sensor_msgs / nav_msgs / geometry_msgs /
// std_msgs / builtin_interfaces .msg files, comments and constants left out) of the types giocal
// imports, for rosbag2 files that do not carry definitions.
#include <map>

#include "import/ros_schema.h"

namespace giocal::import {

namespace {

const char* kHeader =
    "MSG: std_msgs/Header\n"
    "builtin_interfaces/Time stamp\n"
    "string frame_id\n"
    "MSG: builtin_interfaces/Time\n"
    "int32 sec\n"
    "uint32 nanosec\n";

const char* kVector3 =
    "MSG: geometry_msgs/Vector3\n"
    "float64 x\n"
    "float64 y\n"
    "float64 z\n";

const char* kQuaternion =
    "MSG: geometry_msgs/Quaternion\n"
    "float64 x\n"
    "float64 y\n"
    "float64 z\n"
    "float64 w\n";

const char* kTwist =
    "MSG: geometry_msgs/Twist\n"
    "Vector3 linear\n"
    "Vector3 angular\n";

}  // namespace

std::string builtinRos2Definition(const std::string& type) {
  const std::string t = type.find("/msg/") != std::string::npos
                            ? type.substr(0, type.find('/')) + type.substr(type.rfind('/'))
                            : type;
  static const std::map<std::string, std::string> kDefinitions{
      {"sensor_msgs/Imu", std::string("std_msgs/Header header\n"
                                      "geometry_msgs/Quaternion orientation\n"
                                      "float64[9] orientation_covariance\n"
                                      "geometry_msgs/Vector3 angular_velocity\n"
                                      "float64[9] angular_velocity_covariance\n"
                                      "geometry_msgs/Vector3 linear_acceleration\n"
                                      "float64[9] linear_acceleration_covariance\n") +
                              kHeader + kQuaternion + kVector3},
      {"nav_msgs/Odometry", std::string("std_msgs/Header header\n"
                                        "string child_frame_id\n"
                                        "geometry_msgs/PoseWithCovariance pose\n"
                                        "geometry_msgs/TwistWithCovariance twist\n") +
                                kHeader +
                                "MSG: geometry_msgs/PoseWithCovariance\n"
                                "Pose pose\n"
                                "float64[36] covariance\n"
                                "MSG: geometry_msgs/Pose\n"
                                "Point position\n"
                                "Quaternion orientation\n"
                                "MSG: geometry_msgs/Point\n"
                                "float64 x\n"
                                "float64 y\n"
                                "float64 z\n" +
                                kQuaternion +
                                "MSG: geometry_msgs/TwistWithCovariance\n"
                                "Twist twist\n"
                                "float64[36] covariance\n" +
                                kTwist + kVector3},
      {"geometry_msgs/TwistStamped", std::string("std_msgs/Header header\n"
                                                 "geometry_msgs/Twist twist\n") +
                                         kHeader + kTwist + kVector3},
      {"sensor_msgs/NavSatFix", std::string("std_msgs/Header header\n"
                                            "sensor_msgs/NavSatStatus status\n"
                                            "float64 latitude\n"
                                            "float64 longitude\n"
                                            "float64 altitude\n"
                                            "float64[9] position_covariance\n"
                                            "uint8 position_covariance_type\n") +
                                    kHeader +
                                    "MSG: sensor_msgs/NavSatStatus\n"
                                    "int8 status\n"
                                    "uint16 service\n"},
  };
  const auto it = kDefinitions.find(t);
  return it == kDefinitions.end() ? "" : it->second;
}

}  // namespace giocal::import
