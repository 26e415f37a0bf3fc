#include "common/io/sensor_logs.h"

#include <cmath>

#include "common/io/csv_table.h"
#include "common/io/data_error.h"

namespace giocal {

namespace {

// Physical limits: times within GPS weeks 0..9999, rates up to 2000 deg/s and accelerations up to
// 20 g (beyond any MEMS range), ground-robot odometry up to 50 m/s and 20 rad/s.
constexpr ColumnRange kTime{0.0, 9999.0 * 604800.0};
constexpr ColumnRange kGyro{-35.0, 35.0};
constexpr ColumnRange kAcc{-200.0, 200.0};
constexpr ColumnRange kSpeed{-50.0, 50.0};
constexpr ColumnRange kYawRate{-20.0, 20.0};

const std::vector<std::string> kImuHeader{"t", "wx", "wy", "wz", "ax", "ay", "az"};
const std::vector<std::string> kOdomHeader{"t", "v", "w"};
const std::vector<std::string> kTruthHeader{"t",  "lat", "lon", "h",  "ve", "vn",
                                            "vu", "qw",  "qx",  "qy", "qz"};

}  // namespace

ImuLogReader::ImuLogReader(const std::string& path)
    : rows_(path, kImuHeader, {kTime, kGyro, kGyro, kGyro, kAcc, kAcc, kAcc}) {}

bool ImuLogReader::next(ImuSample& s) {
  if (!rows_.next(row_)) return false;
  s.t = row_[0];
  s.gyro = {row_[1], row_[2], row_[3]};
  s.acc = {row_[4], row_[5], row_[6]};
  return true;
}

OdomLogReader::OdomLogReader(const std::string& path)
    : rows_(path, kOdomHeader, {kTime, kSpeed, kYawRate}) {}

bool OdomLogReader::next(OdomSample& s) {
  if (!rows_.next(row_)) return false;
  s = {row_[0], row_[1], row_[2]};
  return true;
}

std::vector<ImuSample> readImuCsv(const std::string& path, std::vector<std::string>* warnings) {
  ImuLogReader reader(path);
  std::vector<ImuSample> out;
  ImuSample s;
  while (reader.next(s)) out.push_back(s);
  if (warnings)
    for (const auto& w : reader.warnings()) warnings->push_back(w);
  return out;
}

void writeImuCsv(const std::string& path, const std::vector<ImuSample>& samples) {
  std::vector<std::vector<double>> rows;
  rows.reserve(samples.size());
  for (const auto& s : samples) {
    rows.push_back({s.t, s.gyro.x(), s.gyro.y(), s.gyro.z(), s.acc.x(), s.acc.y(), s.acc.z()});
  }
  writeCsvTable(path, kImuHeader, rows);
}

std::vector<OdomSample> readOdomCsv(const std::string& path, std::vector<std::string>* warnings) {
  OdomLogReader reader(path);
  std::vector<OdomSample> out;
  OdomSample s;
  while (reader.next(s)) out.push_back(s);
  if (warnings)
    for (const auto& w : reader.warnings()) warnings->push_back(w);
  return out;
}

void writeOdomCsv(const std::string& path, const std::vector<OdomSample>& samples) {
  std::vector<std::vector<double>> rows;
  rows.reserve(samples.size());
  for (const auto& s : samples) rows.push_back({s.t, s.v, s.w});
  writeCsvTable(path, kOdomHeader, rows);
}

namespace {
const ColumnRange kVel{-500.0, 500.0}, kUnit{-1.0001, 1.0001};
}  // namespace

TruthLogReader::TruthLogReader(const std::string& path)
    : rows_(path, kTruthHeader,
            {kTime,
             {-90.0, 90.0},
             {-180.0, 180.0},
             {-1000.0, 100000.0},
             kVel,
             kVel,
             kVel,
             kUnit,
             kUnit,
             kUnit,
             kUnit}) {}

bool TruthLogReader::next(TruthSample& s) {
  if (!rows_.next(row_)) return false;
  const auto& r = row_;
  s.t = r[0];
  s.lat_deg = r[1];
  s.lon_deg = r[2];
  s.h = r[3];
  s.v_enu = {r[4], r[5], r[6]};
  s.q_n_b = Eigen::Quaterniond(r[7], r[8], r[9], r[10]);
  if (std::fabs(s.q_n_b.norm() - 1.0) > 1e-3) {
    throw DataError(rows_.path(), rows_.line(), "quaternion qw,qx,qy,qz is not of unit norm");
  }
  s.q_n_b.normalize();
  return true;
}

std::vector<TruthSample> readTruthCsv(const std::string& path, std::vector<std::string>* warnings) {
  TruthLogReader reader(path);
  std::vector<TruthSample> out;
  TruthSample s;
  while (reader.next(s)) out.push_back(s);
  if (warnings)
    for (const auto& w : reader.warnings()) warnings->push_back(w);
  return out;
}

const std::vector<std::string>& truthCsvHeader() { return kTruthHeader; }

std::vector<double> truthCsvRow(const TruthSample& s) {
  return {s.t,         s.lat_deg,   s.lon_deg,   s.h,         s.v_enu.x(), s.v_enu.y(),
          s.v_enu.z(), s.q_n_b.w(), s.q_n_b.x(), s.q_n_b.y(), s.q_n_b.z()};
}

void writeTruthCsv(const std::string& path, const std::vector<TruthSample>& samples) {
  std::vector<std::vector<double>> rows;
  rows.reserve(samples.size());
  for (const auto& s : samples) rows.push_back(truthCsvRow(s));
  writeCsvTable(path, kTruthHeader, rows);
}

}  // namespace giocal
