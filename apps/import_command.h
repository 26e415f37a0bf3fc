// `giocal import --ubx <file.ubx> | --bag <file.bag> [--imu-topic t] [--odom-topic t]
// [--fix-topic t] --out <dir> [--overwrite]`: a receiver's log to RINEX 3.04 observation and
// navigation files, or a ROS bag's IMU, wheel odometry and GNSS fixes to a dataset folder.
#pragma once

#include <iosfwd>
#include <string>

#include "common/io/stop_request.h"

namespace giocal {

struct ImportJob {
  std::string ubx, bag, out;
  std::string imu_topic, odom_topic, fix_topic;  // empty: found by message type
  bool overwrite = false;
  bool quiet = false;  // no progress line
  const StopRequest* stop = nullptr;
};

/// UBX: writes <out>/rover.obs, <out>/nav.rnx and <out>/import.json (what was read, skipped and
/// damaged) as one set. Bag: writes imu.csv, odom.csv, gnss.pos (NavSatFix, when present),
/// dataset.yaml and import.json as one set. Prints the counts and every warning.
void runImport(const ImportJob& job, std::ostream& log);

}  // namespace giocal
