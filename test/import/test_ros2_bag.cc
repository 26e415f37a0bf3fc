// rosbag2 (ROS 2) sqlite3 databases written here with Debian's sqlite3 in the schema of
// rosbag2_storage_default_plugins, CDR messages, with (Iron) and without (Humble) stored
// definitions: imported as the ROS 1 bags are.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <cmath>

#include "import/bag_dataset.h"
#include "import/bag_source.h"
#include "import/ros_schema.h"
#include "temp_dir.h"

namespace giocal::import {
namespace {

class Db {
 public:
  explicit Db(const std::string& path) { sqlite3_open(path.c_str(), &db_); }
  ~Db() { sqlite3_close(db_); }
  void exec(const std::string& sql) {
    char* err = nullptr;
    ASSERT_EQ(sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &err), SQLITE_OK) << err;
  }
  void message(int topic, double t, const std::vector<uint8_t>& data) {
    sqlite3_stmt* s = nullptr;
    sqlite3_prepare_v2(db_, "INSERT INTO messages (topic_id, timestamp, data) VALUES (?, ?, ?)", -1,
                       &s, nullptr);
    sqlite3_bind_int(s, 1, topic);
    sqlite3_bind_int64(s, 2, static_cast<sqlite3_int64>(std::llround(t * 1e9)));
    sqlite3_bind_blob(s, 3, data.data(), static_cast<int>(data.size()), SQLITE_TRANSIENT);
    EXPECT_EQ(sqlite3_step(s), SQLITE_DONE);
    sqlite3_finalize(s);
  }

 private:
  sqlite3* db_ = nullptr;
};

// Iron's Imu here has one more field than the builtin definition, which only the stored
// definition describes.
std::string ironImuDefinition() {
  std::string def = builtinRos2Definition("sensor_msgs/msg/Imu");
  return def.insert(def.find("MSG:"), "uint8 extra\n");
}

std::vector<uint8_t> cdr(const std::string& type, RosMessage m, double stamp,
                         const std::string& definition = "") {
  m.set("header.stamp.sec", std::floor(stamp));
  m.set("header.stamp.nanosec", std::round((stamp - std::floor(stamp)) * 1e9));
  return m.encode(RosSchema(type, definition.empty() ? builtinRos2Definition(type) : definition),
                  RosEncoding::kCdr);
}

void writeBag(const std::string& path, bool iron) {
  Db db(path);
  db.exec(
      "CREATE TABLE topics (id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL, "
      "serialization_format TEXT NOT NULL, offered_qos_profiles TEXT NOT NULL);"
      "CREATE TABLE messages (id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL, "
      "timestamp INTEGER NOT NULL, data BLOB NOT NULL);"
      "INSERT INTO topics VALUES (1, '/imu', 'sensor_msgs/msg/Imu', 'cdr', ''),"
      "(2, '/wheel', 'geometry_msgs/msg/TwistStamped', 'cdr', ''),"
      "(3, '/gps', 'sensor_msgs/msg/NavSatFix', 'cdr', ''),"
      "(4, '/chatter', 'std_msgs/msg/String', 'cdr', '');");
  if (iron) {
    db.exec(
        "CREATE TABLE message_definitions (id INTEGER PRIMARY KEY, topic_type TEXT NOT NULL, "
        "encoding TEXT NOT NULL, encoded_message_definition TEXT NOT NULL, "
        "type_description_hash TEXT NOT NULL);"
        "INSERT INTO message_definitions VALUES (1, 'sensor_msgs/msg/Imu', 'ros2msg', '" +
        ironImuDefinition() + "', '');");
  }
  const double t0 = 1700000000.0;
  for (int k = 0; k < 200; ++k) {
    const double t = t0 + 0.01 * k;
    RosMessage imu;
    imu.set("angular_velocity.z", 0.001 * k);
    imu.set("linear_acceleration.z", 9.8);
    imu.set("extra", 7);
    db.message(1, t + 0.001, cdr("sensor_msgs/msg/Imu", imu, t, iron ? ironImuDefinition() : ""));
    if (k % 10 == 0) {
      RosMessage w;
      w.set("twist.linear.x", 2.0);
      w.set("twist.angular.z", 0.1 * k);
      db.message(2, t + 0.002, cdr("geometry_msgs/msg/TwistStamped", w, t));
      RosMessage f;
      f.set("latitude", 48.0);
      f.set("longitude", 11.0);
      f.set("position_covariance_type", 0);
      db.message(3, t + 0.003, cdr("sensor_msgs/msg/NavSatFix", f, t));
      db.message(4, t, {0, 1, 0, 0, 3, 0, 0, 0, 'h', 'i', 0});
    }
  }
}

TEST(Ros2Bag, HumbleAndIronDatabasesImport) {
  for (bool iron : {false, true}) {
    test::TempDir dir;
    std::filesystem::create_directories(dir.file("bag"));
    writeBag(dir.file("bag/bag_0.db3"), iron);
    const auto bag = openBag(dir.file("bag"));  // the folder, as ros2 bag record writes it
    EXPECT_EQ(bag->topics().size(), 4u);
    const BagDataset d = readBagDataset(*bag, {});
    ASSERT_EQ(d.imu.size(), 200u);
    ASSERT_EQ(d.odom.size(), 20u);
    ASSERT_EQ(d.fixes.size(), 20u);
    EXPECT_DOUBLE_EQ(d.imu[50].gyro.z(), 0.05);
    EXPECT_DOUBLE_EQ(d.odom[3].w, 3.0);
    EXPECT_EQ(d.leap_seconds, 18);
    // Covariance type 0 (unknown): a single-point sigma of 5 m horizontally.
    EXPECT_NEAR(d.fixes[0].cov_e.trace(), 25.0 + 25.0 + 100.0, 1e-6);
  }
  test::TempDir dir;
  const std::string junk = dir.write("junk.db3", "not a database at all, just text");
  EXPECT_THROW(openBag(junk), std::runtime_error);
  std::filesystem::create_directories(dir.file("empty"));
  try {
    openBag(dir.file("empty"));
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("a folder without a rosbag2 .db3 file"),
              std::string::npos);
  }
}

}  // namespace
}  // namespace giocal::import
