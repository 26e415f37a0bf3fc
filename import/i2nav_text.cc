#include "import/i2nav_text.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>

#include "common/geodesy/wgs84.h"
#include "common/io/data_error.h"
#include "common/math/rotation.h"
#include "common/time/gps_time.h"

namespace giocal::import {
namespace {

constexpr double kMinInterval = 1e-4;  // [s]: rows closer than this (10 kHz) are out of order

// Rows of numbers separated by blanks or commas; '#' and '%' lines and blank lines are skipped.
// Damage it can step over (a truncated last line, rows out of time order) goes to `warnings`.
class NumberRows {
 public:
  NumberRows(std::string path, std::vector<std::string>* warnings)
      : path_(std::move(path)), in_(path_), warnings_(warnings ? *warnings : local_) {
    if (!in_) throw DataError(path_, 0, "cannot open the file");
  }
  /// The next row with at least `min_columns` numbers; false at the end. A shorter last line is
  /// a truncated file: a warning, and the end.
  bool next(std::vector<double>& row, size_t min_columns) {
    std::string text;
    while (std::getline(in_, text)) {
      ++line_;
      const size_t first = text.find_first_not_of(" \t\r,");
      if (first == std::string::npos || text[first] == '#' || text[first] == '%') continue;
      row.clear();
      const char* p = text.c_str() + first;
      while (*p) {
        char* end = nullptr;
        const double v = std::strtod(p, &end);
        if (end == p)
          throw DataError(path_, line_, "not a number: '" + std::string(p).substr(0, 12) + "'");
        if (!std::isfinite(v)) throw DataError(path_, line_, "a value is not finite");
        row.push_back(v);
        p = end;
        while (*p == ' ' || *p == '\t' || *p == '\r' || *p == ',') ++p;
      }
      if (row.size() >= min_columns) return true;
      if (in_.peek() == std::char_traits<char>::eof()) {
        warnings_.push_back(path_ + ":" + std::to_string(line_) +
                            ": truncated last line dropped (" + std::to_string(row.size()) +
                            " of " + std::to_string(min_columns) + " columns)");
        return end();
      }
      throw DataError(
          path_, line_,
          std::to_string(row.size()) + " columns, expected " + std::to_string(min_columns));
    }
    return end();
  }
  /// The current row is dropped: its time is not after the previous one's (the first is named).
  void dropOutOfOrder() {
    if (out_of_order_++ == 0) {
      warnings_.push_back(path_ + ":" + std::to_string(line_) +
                          ": time not after the previous row's: row dropped (later ones counted)");
    }
  }
  long line() const { return line_; }

 private:
  bool end() {
    if (out_of_order_ > 1) {
      warnings_.push_back(path_ + ": " + std::to_string(out_of_order_) +
                          " rows out of time order dropped");
    }
    return false;
  }
  std::string path_;
  std::ifstream in_;
  std::vector<std::string> local_;
  std::vector<std::string>& warnings_;
  long line_ = 0;
  long out_of_order_ = 0;
};

double medianOf(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

}  // namespace

I2navImu readI2navImu(const std::string& path, int week, double odometer_period) {
  I2navImu out;
  NumberRows rows(path, &out.warnings);
  // t (GPS seconds), increments, speed, interval, line
  std::vector<std::vector<double>> raw;
  std::vector<double> row;
  double t_prev = static_cast<double>(week) * kSecondsPerWeek, sow_prev = 0.0;
  while (rows.next(row, out.columns == 0 ? 7 : static_cast<size_t>(out.columns))) {
    if (out.columns == 0) {
      out.columns = static_cast<int>(row.size());
      if (out.columns > 9) {
        throw DataError(path, rows.line(),
                        std::to_string(out.columns) + " columns: an i2Nav IMU text has 7 to 9");
      }
    }
    if (row[0] < 0.0 || row[0] >= kSecondsPerWeek) {
      throw DataError(path, rows.line(),
                      "time " + std::to_string(row[0]) + " is not a second of week");
    }
    const double t = gpsSecondsNear(row[0], t_prev);
    // The interval from the times of week (GPS seconds near 1.4e9 keep only 0.2 us).
    double dt = raw.empty() ? 0.0 : row[0] - sow_prev;
    if (dt < 0.0) dt += kSecondsPerWeek;
    if (!raw.empty() && (t <= raw.back()[0] || dt < kMinInterval)) {
      rows.dropOutOfOrder();
      continue;
    }
    t_prev = t;
    sow_prev = row[0];
    double speed = 0.0;
    if (out.columns == 8) speed = row[7];
    if (out.columns == 9) speed = 0.5 * (row[7] + row[8]);
    raw.push_back({t, row[1], row[2], row[3], row[4], row[5], row[6], speed, dt,
                   static_cast<double>(rows.line())});
  }
  if (raw.size() < 2) throw DataError(path, rows.line(), "fewer than two IMU rows");
  std::vector<double> dts;
  for (size_t k = 1; k < raw.size() && k <= 1000; ++k) dts.push_back(raw[k][8]);
  out.period = medianOf(dts);
  long gaps = 0;
  double block_t = 0.0, block_v = 0.0, block_start = NAN;
  int block_n = 0;
  for (size_t k = 1; k < raw.size(); ++k) {
    const std::vector<double>& r = raw[k];
    double dt = r[8];
    if (dt > 2.0 * out.period) {
      if (gaps++ == 0) {
        out.warnings.push_back(path + ": gap of " + std::to_string(dt) + " s before t=" +
                               std::to_string(r[0]) + " (its increments taken over one period)");
      }
      dt = out.period;
    }
    ImuSample s;
    s.t = r[0] - 0.5 * dt;
    s.gyro = Eigen::Vector3d(r[1], r[2], r[3]) / dt;
    s.acc = Eigen::Vector3d(r[4], r[5], r[6]) / dt;
    // imu.csv's and odom.csv's physical limits (2000 deg/s, 20 g, 50 m/s).
    if (!(s.gyro.cwiseAbs().maxCoeff() <= 35.0 && s.acc.cwiseAbs().maxCoeff() <= 200.0 &&
          std::abs(r[7]) <= 50.0)) {
      throw DataError(path, static_cast<long>(r[9]),
                      "increments or speed beyond a vehicle's IMU and odometer (rates over 35 "
                      "rad/s or 200 m/s^2, or a speed over 50 m/s): not radians and m/s over the "
                      "interval?");
    }
    out.imu.push_back(s);
    if (out.columns == 7) continue;
    if (std::isnan(block_start)) block_start = s.t;
    block_t += s.t;
    block_v += r[7];
    ++block_n;
    if (s.t - block_start + out.period >= odometer_period - 0.5 * out.period) {
      out.odom.push_back({block_t / block_n, block_v / block_n, 0.0});
      block_t = block_v = 0.0;
      block_n = 0;
      block_start = NAN;
    }
  }
  return out;
}

std::vector<RtkSolution> readI2navPos(const std::string& path, int week,
                                      std::vector<std::string>* warnings) {
  NumberRows rows(path, warnings);
  std::vector<RtkSolution> out;
  std::vector<double> r;
  double t_prev = static_cast<double>(week) * kSecondsPerWeek;
  while (rows.next(r, 7)) {
    if (r[0] < 0.0 || r[0] >= kSecondsPerWeek || std::abs(r[1]) > 90.0 || std::abs(r[2]) > 360.0 ||
        std::abs(r[3]) > 1e5 || r[4] < 0.0 || r[5] < 0.0 || r[6] < 0.0) {
      throw DataError(path, rows.line(),
                      "time of week, latitude, longitude, height or sigma out of range");
    }
    const double t = gpsSecondsNear(r[0], t_prev);
    if (!out.empty() && t <= out.back().t) {
      rows.dropOutOfOrder();
      continue;
    }
    t_prev = t;
    RtkSolution s;
    s.t = t;
    const double lat = r[1] * kDegToRad, lon = r[2] * kDegToRad;
    s.p_e = ecefFromGeodetic({lat, lon, r[3]});
    const Eigen::Matrix3d R_e_l = rotationEcefFromEnu(lat, lon);
    const Eigen::Vector3d var_enu(r[5] * r[5], r[4] * r[4], r[6] * r[6]);
    s.cov_e = R_e_l * var_enu.asDiagonal() * R_e_l.transpose();
    const double sd_h = std::max(r[4], r[5]);
    s.quality = sd_h < 0.05 ? 1 : sd_h < 0.5 ? 2 : 5;
    out.push_back(s);
  }
  if (out.empty()) throw DataError(path, rows.line(), "no position rows");
  return out;
}

std::vector<TruthSample> readI2navNav(const std::string& path, std::vector<std::string>* warnings) {
  NumberRows rows(path, warnings);
  std::vector<TruthSample> out;
  std::vector<double> r;
  // NED to ENU: x_enu = (x_ned.y, x_ned.x, -x_ned.z).
  Eigen::Matrix3d R_enu_ned;
  R_enu_ned << 0, 1, 0, 1, 0, 0, 0, 0, -1;
  while (rows.next(r, 11)) {
    if (r[0] < 0.0 || r[0] > 9999.0 || r[1] < 0.0 || r[1] >= kSecondsPerWeek ||
        std::abs(r[2]) > 90.0 || std::abs(r[3]) > 360.0) {
      throw DataError(path, rows.line(), "week, time of week, latitude or longitude out of range");
    }
    TruthSample s;
    s.t = gpsSecondsFromWeekTime({static_cast<int>(r[0]), r[1]});
    if (!out.empty() && s.t <= out.back().t) {
      rows.dropOutOfOrder();
      continue;
    }
    s.lat_deg = r[2];
    s.lon_deg = r[3];
    s.h = r[4];
    s.v_enu = R_enu_ned * Eigen::Vector3d(r[5], r[6], r[7]);
    const Eigen::Vector3d rpy(r[8] * kDegToRad, r[9] * kDegToRad, r[10] * kDegToRad);
    const Eigen::Matrix3d R_ned_b = (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
                                     Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
                                     Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
                                        .toRotationMatrix();
    s.q_n_b = Eigen::Quaterniond(R_enu_ned * R_ned_b).normalized();
    out.push_back(s);
  }
  if (out.empty()) throw DataError(path, rows.line(), "no navigation rows");
  return out;
}

int firstWeekOfI2navNav(const std::string& path) {
  NumberRows rows(path, nullptr);
  std::vector<double> r;
  if (!rows.next(r, 11)) throw DataError(path, rows.line(), "no navigation rows");
  if (r[0] < 0.0 || r[0] > 9999.0) throw DataError(path, rows.line(), "week out of range");
  return static_cast<int>(r[0]);
}

}  // namespace giocal::import
