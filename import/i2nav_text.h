// Readers of the i2Nav text formats (KF-GINS, OB_GINS, awesome-gins-datasets): the IMU text of
// angle and velocity increments with an optional odometer speed column, the GNSS position file
// (.pos, 7 columns) and the reference navigation file (.nav, 11 columns).
#pragma once

#include <string>
#include <vector>

#include "common/gnss/rtk.h"
#include "common/imu/imu_sample.h"
#include "common/io/sensor_logs.h"
#include "common/odometer/odom_sample.h"

namespace giocal::import {

struct I2navImu {
  std::vector<ImuSample> imu;    // rates at the middle of each increment's interval
  std::vector<OdomSample> odom;  // speed only (w = 0), averaged over odometer_period
  int columns = 0;               // 7: no odometer, 8: one speed, 9: two (their mean)
  double period = 0.0;           // the IMU's sampling period (median interval) [s]
  std::vector<std::string> warnings;
};

/// Rows: GNSS seconds of week, x-y-z angle increments [rad], x-y-z velocity increments [m/s]
/// over the interval ending at that time, then optionally one or two odometer speeds [m/s]
/// (OB_GINS's convention: two are averaged). `week`: the GPS week of the first row (times of
/// week that wrap count into the next). The first row only opens the first interval; after a
/// gap (over twice the median period) the increments are taken over one period. A row out of
/// time order (or within 0.1 ms of the previous) is dropped with a warning; increments beyond
/// imu.csv's physical limits throw DataError naming the line; a short or non-numeric row throws DataError naming the
/// line, except a truncated last line (dropped with a warning).
I2navImu readI2navImu(const std::string& path, int week, double odometer_period);

/// Rows: GNSS seconds of week, latitude, longitude [deg], ellipsoidal height, latitude,
/// longitude and height standard deviations [m]. RTKLIB's quality is inferred from the
/// horizontal sigma (1 under 5 cm, 2 under 0.5 m, else 5).
std::vector<RtkSolution> readI2navPos(const std::string& path, int week,
                                      std::vector<std::string>* warnings);

/// Rows: GNSS week, seconds of week, latitude, longitude [deg], height [m], north-east-down
/// velocity [m/s], roll, pitch, yaw [deg] of the FRD IMU frame in NED (ZYX Euler angles); as
/// truth.csv rows (ENU velocity, q_n_b in the local ENU frame).
std::vector<TruthSample> readI2navNav(const std::string& path, std::vector<std::string>* warnings);

/// The GPS week of the first row of an i2Nav .nav file; throws DataError if it has none.
int firstWeekOfI2navNav(const std::string& path);

}  // namespace giocal::import
