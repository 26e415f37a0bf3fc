// RosMessage: one serialized ROS message read through its schema into named values ("header.stamp
// .sec", "angular_velocity.x", "meas[3].prMes"); ROS 1 serialization (rosbag) and ROS 2's CDR
// (rosbag2). RosMessage also writes messages back, for the tests' bags.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "import/ros_schema.h"

namespace giocal::import {

enum class RosEncoding { kRos1, kCdr };

class RosMessage {
 public:
  /// Reads `size` bytes; throws std::runtime_error naming the field where the bytes end early or a
  /// length is impossible.
  static RosMessage decode(const RosSchema& schema, RosEncoding encoding, const uint8_t* data,
                           std::size_t size);

  bool has(const std::string& path) const { return numbers_.count(path) > 0; }
  /// The number at `path`; throws std::runtime_error naming the path when the message lacks it.
  double number(const std::string& path) const;
  const std::string& text(const std::string& path) const;
  /// Elements of the variable-length array at `path` (0 when absent).
  std::size_t length(const std::string& path) const;
  /// A time field (ROS 1 "time": sec/nsec; ROS 2 builtin_interfaces/Time: sec/nanosec) [s].
  double time(const std::string& path) const;

  void set(const std::string& path, double v) { numbers_[path] = v; }
  void setText(const std::string& path, const std::string& v) { texts_[path] = v; }
  void setLength(const std::string& path, std::size_t n) { lengths_[path] = n; }
  /// The message serialized by `schema` (values not set are zero or empty).
  std::vector<uint8_t> encode(const RosSchema& schema, RosEncoding encoding) const;

 private:
  friend class RosCodec;
  std::map<std::string, double> numbers_;
  std::map<std::string, std::string> texts_;
  std::map<std::string, std::size_t> lengths_;
};

}  // namespace giocal::import
