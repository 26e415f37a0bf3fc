// ROS message definitions and the two wire formats (ROS 1 serialization, ROS 2 CDR): fields by
// name through nested types, arrays, strings and times; damage reported by field, not read past.
#include <gtest/gtest.h>

#include <stdexcept>

#include "import/ros_message.h"
#include "import/ros_schema.h"

namespace giocal::import {
namespace {

const char* kDefinition =
    "# a comment\n"
    "Header header\n"
    "uint8 KIND_A=1  # a constant, not a field\n"
    "geometry_msgs/Vector3 v\n"
    "float64[3] fixed\n"
    "Item[] items\n"
    "string name\n"
    "================\n"
    "MSG: std_msgs/Header\n"
    "uint32 seq\n"
    "time stamp\n"
    "string frame_id\n"
    "================\n"
    "MSG: geometry_msgs/Vector3\n"
    "float64 x\n"
    "float64 y\n"
    "float64 z\n"
    "================\n"
    "MSG: test_msgs/Item\n"
    "int8 a\n"
    "uint16 b\n"
    "float32 c\n";

RosMessage sample() {
  RosMessage m;
  m.set("header.seq", 7);
  m.set("header.stamp.sec", 1432235498);
  m.set("header.stamp.nsec", 123456789);
  m.setText("header.frame_id", "imu_link");
  m.set("v.x", 0.5);
  m.set("v.y", -9.81);
  m.set("v.z", 1e-3);
  for (int k = 0; k < 3; ++k) m.set("fixed[" + std::to_string(k) + "]", k * 1.5);
  m.setLength("items", 2);
  m.set("items[0].a", -3);
  m.set("items[0].b", 65000);
  m.set("items[0].c", 0.25);
  m.set("items[1].a", 4);
  m.set("items[1].b", 2);
  m.set("items[1].c", -8.5);
  m.setText("name", "giocal");
  return m;
}

TEST(RosMessage, BothWireFormatsRoundTrip) {
  const RosSchema schema("test_msgs/Sample", kDefinition);
  EXPECT_EQ(schema.fieldsOf("test_msgs/Sample").size(), 5u);  // the constant is not a field
  for (RosEncoding enc : {RosEncoding::kRos1, RosEncoding::kCdr}) {
    const std::vector<uint8_t> bytes = sample().encode(schema, enc);
    const RosMessage m = RosMessage::decode(schema, enc, bytes.data(), bytes.size());
    EXPECT_DOUBLE_EQ(m.time("header.stamp"), 1432235498.123456789);
    EXPECT_EQ(m.text("header.frame_id"), "imu_link");
    EXPECT_DOUBLE_EQ(m.number("v.y"), -9.81);
    EXPECT_DOUBLE_EQ(m.number("fixed[2]"), 3.0);
    EXPECT_EQ(m.length("items"), 2u);
    EXPECT_DOUBLE_EQ(m.number("items[0].a"), -3);
    EXPECT_DOUBLE_EQ(m.number("items[0].b"), 65000);
    EXPECT_DOUBLE_EQ(m.number("items[1].c"), -8.5);
    EXPECT_EQ(m.text("name"), "giocal");
    EXPECT_THROW(m.number("v.w"), std::runtime_error);
  }
  // ROS 1 is packed: 4 + 8 + 4+8 (header) + 24 + 24 + 4 + 2 * 7 + 4+6 bytes.
  EXPECT_EQ(sample().encode(schema, RosEncoding::kRos1).size(), 100u);
}

TEST(RosMessage, DamageIsNamedAndNeverReadPast) {
  const RosSchema schema("test_msgs/Sample", kDefinition);
  std::vector<uint8_t> bytes = sample().encode(schema, RosEncoding::kRos1);
  bytes.resize(bytes.size() - 3);
  try {
    RosMessage::decode(schema, RosEncoding::kRos1, bytes.data(), bytes.size());
    FAIL() << "a cut message was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("ends inside 'name'"), std::string::npos) << e.what();
  }
  // An element count far beyond the bytes left is damage, not an allocation.
  std::vector<uint8_t> big = sample().encode(schema, RosEncoding::kRos1);
  big[73] = big[74] = big[75] = 0x7F;  // the count of items (bytes 72-75)
  EXPECT_THROW(RosMessage::decode(schema, RosEncoding::kRos1, big.data(), big.size()),
               std::runtime_error);
  EXPECT_THROW(RosSchema("a/B", "Unknown field\n"), std::runtime_error);
  EXPECT_THROW(RosSchema("a/B", "float64\n"), std::runtime_error);
  // A definition that refers to itself stops at a depth limit instead of recursing forever.
  const RosSchema cyclic("a/B", "B inner\nMSG: a/B\nB inner\n");
  EXPECT_THROW(RosMessage::decode(cyclic, RosEncoding::kRos1, bytes.data(), bytes.size()),
               std::runtime_error);
}

TEST(RosMessage, BuiltinRos2DefinitionsReadTheirTypes) {
  for (const char* type : {"sensor_msgs/msg/Imu", "nav_msgs/msg/Odometry",
                           "geometry_msgs/msg/TwistStamped", "sensor_msgs/msg/NavSatFix"}) {
    const RosSchema schema(type, builtinRos2Definition(type));
    RosMessage m;
    m.set("header.stamp.sec", 1700000000);
    m.set("header.stamp.nanosec", 5);
    const auto bytes = m.encode(schema, RosEncoding::kCdr);
    EXPECT_DOUBLE_EQ(RosMessage::decode(schema, RosEncoding::kCdr, bytes.data(), bytes.size())
                         .time("header.stamp"),
                     1700000000.000000005)
        << type;
  }
  EXPECT_EQ(builtinRos2Definition("std_msgs/msg/String"), "");
}

}  // namespace
}  // namespace giocal::import
