// `giocal import --ubx <file.ubx> | --bag <file.bag> [--imu-topic t] [--odom-topic t]
// [--fix-topic t] | --i2nav-imu <imu.txt> [--i2nav-pos f] [--i2nav-nav f] [--gps-week n]
// [--lever-arm x,y,z] --out <dir> [--overwrite]`: a receiver's log to RINEX 3.04 observation and
// navigation files, or a ROS bag's or i2Nav text logs' IMU, odometry and GNSS positions to a
// dataset folder.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "common/io/dataset_description.h"
#include "common/io/output_set.h"
#include "common/io/stop_request.h"

namespace giocal {

struct ImportJob {
  std::string ubx, bag, out;
  std::string imu_topic, odom_topic, fix_topic;  // empty: found by message type
  std::string stamps = "auto";  // a bag's times: auto, header (stamps) or record (receive times)
  std::string i2nav_imu, i2nav_pos, i2nav_nav;  // i2Nav text logs
  int gps_week = -1;                            // of the i2Nav IMU's first row; -1: the .nav's
  std::string lever_arm;                        // "x,y,z" antenna in the IMU frame [m]
  bool overwrite = false;
  bool quiet = false;  // no progress line
  const StopRequest* stop = nullptr;
};

/// UBX: writes <out>/rover.obs, <out>/nav.rnx and <out>/import.json (what was read, skipped and
/// damaged) as one set. Bag: writes imu.csv, odom.csv, gnss.pos (NavSatFix, when present),
/// dataset.yaml and import.json as one set. i2Nav: imu.csv, odom.csv (speed only), gnss.pos,
/// truth.csv (from the .nav), dataset.yaml and import.json. Prints the counts and every warning.
void runImport(const ImportJob& job, std::ostream& log);

/// Writes `d` as dataset.yaml into the set (d.folder becomes its staging folder); its size.
std::uintmax_t stageDatasetDescription(OutputSet& outputs, DatasetDescription& d);

/// Throws unless job.overwrite when one of `files` exists in job.out.
void refuseToOverwrite(const ImportJob& job, const std::vector<std::string>& files);

}  // namespace giocal
