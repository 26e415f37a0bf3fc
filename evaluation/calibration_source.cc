#include "evaluation/calibration_source.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>

#include "common/calibration/calibration_run.h"
#include "common/io/csv_table.h"
#include "common/io/data_error.h"
#include "common/io/output_set.h"
#include "common/io/text.h"
#include "common/math/rotation.h"
#include "evaluation/dead_reckoning.h"

namespace giocal {
namespace {

/// The odometer delay the run took out before calibrating (summary.json's
/// odometer_delay.applied_s): the calibration holds with the stamps corrected by it.
double appliedDelay(const nlohmann::json& summary) {
  if (!summary.contains("odometer_delay") || !summary["odometer_delay"].is_object()) return 0.0;
  const auto& d = summary["odometer_delay"];
  return d.contains("applied_s") && d["applied_s"].is_number() ? d["applied_s"].get<double>() : 0.0;
}

CalibrationSource fromSummary(const std::string& path) {
  verifyOutputSet(path);
  std::ifstream in(path);
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.contains("final") || j["final"].is_null() ||
      !j.contains("covariance_tangent")) {
    throw DataError(path, 0, "no final calibration with its covariance_tangent in it");
  }
  CalibrationSource s;
  try {
    const auto& f = j["final"];
    s.calibration.mean.s_v = f["s_v"].get<double>();
    s.calibration.mean.s_w = f["s_w"].get<double>();
    const auto p = f["p_b_m"].get<std::vector<double>>();
    const auto q = f["q_b_m"].get<std::vector<double>>();
    const auto C = j["covariance_tangent"].get<std::vector<std::vector<double>>>();
    if (p.size() != 3 || q.size() != 4 || C.size() != 8) throw std::runtime_error("sizes");
    s.calibration.mean.p_b_m = Eigen::Vector3d(p[0], p[1], p[2]);
    s.calibration.mean.q_b_m = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized();
    Eigen::Matrix<double, 8, 8> cov;
    for (int r = 0; r < 8; ++r) {
      if (C[static_cast<size_t>(r)].size() != 8) throw std::runtime_error("sizes");
      for (int c = 0; c < 8; ++c) cov(r, c) = C[static_cast<size_t>(r)][static_cast<size_t>(c)];
    }
    if (!cov.allFinite()) throw std::runtime_error("not finite");
    s.calibration.covariance = cov;
    if (f.contains("t_d_odo")) s.odometer_delay_s = f["t_d_odo"].get<double>();
    if (!std::isfinite(s.odometer_delay_s)) throw std::runtime_error("t_d_odo not finite");
    s.odometer_delay_s += appliedDelay(j);
    if (f.contains("gyro_tilt_deg")) {
      const auto d = f["gyro_tilt_deg"].get<std::vector<double>>();
      if (d.size() != 2) throw std::runtime_error("gyro_tilt_deg: sizes");
      s.gyro_tilt = Eigen::Vector2d(d[0], d[1]) * kDegToRad;
      const auto sd = j["sd"]["gyro_tilt_deg"].get<std::vector<double>>();
      if (sd.size() != 2) throw std::runtime_error("sd.gyro_tilt_deg: sizes");
      s.gyro_tilt_sd = std::max(sd[0], sd[1]) * kDegToRad;
      if (!s.gyro_tilt.allFinite() || !(s.gyro_tilt_sd > 0.0))
        throw std::runtime_error("gyro_tilt_deg or its sd not finite");
    }
  } catch (const std::exception& e) {
    throw DataError(path, 0, std::string("bad final calibration or covariance: ") + e.what());
  }
  s.label = path;
  return s;
}

// The table's last row at or before time t (column 0), or none.
std::optional<std::vector<double>> lastRowAtOrBefore(const CsvTable& table, double t) {
  std::optional<std::vector<double>> row;
  for (const auto& r : table.rows) {
    if (r[0] <= t + 1e-9) row = r;
  }
  return row;
}

// The same of the file `path`, or none when the file does not exist.
std::optional<std::vector<double>> rowAt(const std::string& path,
                                         const std::vector<std::string>& header, double t) {
  if (!std::filesystem::exists(path)) return std::nullopt;
  return lastRowAtOrBefore(readCsvTable(path, header, {}), t);
}

CalibrationSource fromCsvAt(const std::string& path, double seconds, double t0) {
  const std::optional<std::vector<double>> row =
      lastRowAtOrBefore(readCsvTable(path, calibrationCsvHeader(), {}), t0 + seconds);
  if (!row) {
    throw DataError(
        path, 0,
        "no row at or before " + std::to_string(seconds) + " s after the data's first rover epoch");
  }
  const std::vector<double>& r = *row;
  CalibrationSource s;
  OdometerCalibration& m = s.calibration.mean;
  m.s_v = r[1];
  m.s_w = r[2];
  m.p_b_m = Eigen::Vector3d(r[3], r[4], r[5]);
  m.q_b_m = Eigen::Quaterniond(rotationFromRpy(Eigen::Vector3d(r[6], r[7], r[8]) * kDegToRad));
  s.calibration.sd_s_v = r[9];
  s.calibration.sd_s_w = r[10];
  s.calibration.sd_p_b_m = Eigen::Vector3d(r[11], r[12], r[13]);
  // The file has roll/pitch/yaw sigmas only: taken as the tangent's (equal for small angles).
  s.calibration.sd_rpy_b_m = Eigen::Vector3d(r[14], r[15], r[16]) * kDegToRad;
  s.label = path + "@" + fixedText(seconds, 1);
  // The optional states' histories beside it, at the same row's time (a run that estimated them
  // would dead-reckon with them from its summary.json too).
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  if (const auto d = rowAt((dir / "odometer_delay.csv").string(), odometerDelayCsvHeader(), r[0]))
    s.odometer_delay_s = (*d)[1];
  if (const auto g = rowAt((dir / "gyro_tilt.csv").string(), gyroTiltCsvHeader(), r[0])) {
    s.gyro_tilt = Eigen::Vector2d((*g)[1], (*g)[2]) * kDegToRad;
    s.gyro_tilt_sd = std::max((*g)[3], (*g)[4]) * kDegToRad;
    if (!s.gyro_tilt.allFinite() || !(s.gyro_tilt_sd > 0.0))
      throw DataError((dir / "gyro_tilt.csv").string(), 0, "tilt or its sd not finite");
  }
  return s;
}

}  // namespace

CalibrationSource readCalibrationSource(const std::string& source, const CalibrationInputs& in) {
  // The truth of this dataset or, after "truth:", of another (a calibration drive's).
  if (source == "truth" || source.rfind("truth:", 0) == 0) {
    if (source == "truth" && !in.truth)
      throw std::runtime_error("--calibration truth: the dataset has no truth_calib.yaml");
    CalibrationSource s;
    const TruthCalibration truth =
        source == "truth" ? *in.truth
                          : readTruthCalibration(source.substr(6) + "/truth_calib.yaml");
    s.calibration.mean = truth.calib;
    s.gyro_tilt = truth.gyro_tilt_deg * kDegToRad;
    s.gyro_tilt_sd = 1e-7;  // as the truth's covariance above
    s.calibration.covariance = Eigen::Matrix<double, 8, 8>::Identity() * 1e-14;
    s.label = source;
    return s;
  }
  if (source == "guess") return {in.description.initial_calibration, "guess"};
  if (source.rfind("guess:", 0) == 0) {
    return {readDatasetDescription(source.substr(6)).initial_calibration, source};
  }
  const size_t at = source.rfind('@');
  if (at != std::string::npos) {
    double seconds = 0.0;
    size_t used = 0;
    try {
      seconds = std::stod(source.substr(at + 1), &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != source.size() - at - 1 || !std::isfinite(seconds)) {
      throw std::runtime_error("--calibration " + source +
                               ": expected <calibration.csv>@<seconds>");
    }
    // Seconds count from the start of the run that wrote the file (its summary.json beside it),
    // else from the first rover epoch of the data being dead-reckoned.
    const std::string csv = source.substr(0, at);
    double t0 = in.rover.epochs.front().t, applied = 0.0;
    std::ifstream beside((std::filesystem::path(csv).parent_path() / "summary.json").string());
    if (beside) {
      const nlohmann::json j = nlohmann::json::parse(beside, nullptr, false);
      if (!j.is_discarded() && j.contains("t_first_rover_epoch") &&
          j["t_first_rover_epoch"].is_number())
        t0 = j["t_first_rover_epoch"].get<double>();
      if (!j.is_discarded()) applied = appliedDelay(j);
    }
    CalibrationSource s = fromCsvAt(csv, seconds, t0);
    s.odometer_delay_s += applied;
    return s;
  }
  if (source.size() >= 5 && source.substr(source.size() - 5) == ".json") return fromSummary(source);
  throw std::runtime_error("--calibration " + source +
                           ": expected <run>/summary.json, <calibration.csv>@<seconds>, truth, "
                           "guess, truth:<dataset> or guess:<dataset>");
}

void applyCalibrationSource(const CalibrationSource& source, DeadReckoningJob& job,
                            std::vector<OdomSample>& odom) {
  job.calibration = source.calibration;
  for (OdomSample& s : odom) s.t -= source.odometer_delay_s;
  if (source.gyro_tilt.allFinite()) {
    job.options.estimate_gyro_tilt = true;
    job.options.gyro_tilt_start = source.gyro_tilt;
    job.options.gyro_tilt_sigma_deg = source.gyro_tilt_sd * kRadToDeg;
  }
}

}  // namespace giocal
