// Readers and writers of the dataset's sensor logs: imu.csv, odom.csv, truth.csv.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "common/imu/imu_sample.h"
#include "common/io/csv_table.h"
#include "common/odometer/odom_sample.h"

namespace giocal {

/// One row of truth.csv: IMU origin (degrees, metres), ENU velocity and attitude q_n_b in the
/// local-level ENU frame at the current position.
struct TruthSample {
  double t = 0.0;
  double lat_deg = 0.0;
  double lon_deg = 0.0;
  double h = 0.0;
  Eigen::Vector3d v_enu = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_n_b = Eigen::Quaterniond::Identity();
};

/// imu.csv and odom.csv read sample by sample (constant memory), with readCsvTable()'s checks.
class ImuLogReader {
 public:
  explicit ImuLogReader(const std::string& path);
  bool next(ImuSample& s);  // false at the end; throws DataError on a bad row
  std::vector<std::string> warnings() const { return rows_.warnings(); }  // damage dropped

 private:
  CsvRowReader rows_;
  std::vector<double> row_;
};

class OdomLogReader {
 public:
  explicit OdomLogReader(const std::string& path);
  bool next(OdomSample& s);
  std::vector<std::string> warnings() const { return rows_.warnings(); }

 private:
  CsvRowReader rows_;
  std::vector<double> row_;
};

/// truth.csv read sample by sample; quaternions must have unit norm within 1e-3 (normalized).
class TruthLogReader {
 public:
  explicit TruthLogReader(const std::string& path);
  bool next(TruthSample& s);
  std::vector<std::string> warnings() const { return rows_.warnings(); }

 private:
  CsvRowReader rows_;
  std::vector<double> row_;
};

/// With `warnings`, the recoverable damage dropped (CsvDamage) is appended to it.
std::vector<ImuSample> readImuCsv(const std::string& path,
                                  std::vector<std::string>* warnings = nullptr);
void writeImuCsv(const std::string& path, const std::vector<ImuSample>& samples);

std::vector<OdomSample> readOdomCsv(const std::string& path,
                                    std::vector<std::string>* warnings = nullptr);
void writeOdomCsv(const std::string& path, const std::vector<OdomSample>& samples);

/// Quaternions must have unit norm within 1e-3 and are normalized on reading.
std::vector<TruthSample> readTruthCsv(const std::string& path,
                                      std::vector<std::string>* warnings = nullptr);
void writeTruthCsv(const std::string& path, const std::vector<TruthSample>& samples);
/// The truth.csv header and one row of it (for writers that stream rows).
const std::vector<std::string>& truthCsvHeader();
std::vector<double> truthCsvRow(const TruthSample& s);

}  // namespace giocal
