#include "apps/check_command.h"

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <map>
#include <nlohmann/json.hpp>
#include <ostream>

#include "common/calibration/coarse_mounting.h"
#include "common/calibration/dataset_diagnosis.h"
#include "common/gnss/rinex_nav.h"
#include "common/gnss/rinex_obs.h"
#include "common/imu/accel_units.h"
#include "common/io/data_error.h"
#include "common/io/dataset_description.h"
#include "common/io/sensor_logs.h"
#include "common/io/time_series_stats.h"
#include "common/math/rotation.h"
#include "common/odometer/gyro_yaw_rate.h"

namespace giocal {

namespace {

void printStats(std::ostream& out, const std::string& name, const std::vector<double>& times) {
  const TimeSeriesStats s = timeSeriesStats(times);
  out << "  " << std::left << std::setw(10) << name << std::right << s.samples << " samples over "
      << std::fixed << std::setprecision(2) << (s.t_last - s.t_first) << " s";
  if (s.median_dt > 0) out << " at " << std::setprecision(1) << 1.0 / s.median_dt << " Hz";
  if (s.gaps > 0) {
    out << ", " << s.gaps << " gap(s), largest " << std::setprecision(3) << s.largest_gap
        << " s at t=" << std::setprecision(3) << s.gap_start;
  }
  out << "\n";
}

template <typename T>
std::vector<double> timesOf(const std::vector<T>& samples) {
  std::vector<double> t;
  t.reserve(samples.size());
  for (const auto& s : samples) t.push_back(s.t);
  return t;
}

// The mounting the drive shows against the dataset's initial guess: a guess far outside its own
// sigma and the data's (a misread mounting, an IMU turned by 90 degrees) is named.
void printMountingCheck(std::ostream& out, const CalibrationPrior& c, const CoarseMounting& m) {
  if (!m.valid) {
    out << "  mounting from the data: not found (" << m.why_not << ")\n";
    return;
  }
  const Vec3 rpy = rpyFromRotation(m.q_b_m.toRotationMatrix()) * kRadToDeg;
  const double apart = m.q_b_m.angularDistance(c.mean.q_b_m);
  const double allowed = 3.0 * std::sqrt(m.sigma_rpy.squaredNorm() + c.sd_rpy_b_m.squaredNorm());
  out << std::setprecision(4) << "  mounting from the data: rpy_b_m [" << rpy.transpose()
      << "] deg, sigma [" << (m.sigma_rpy * kRadToDeg).transpose() << "] deg; the initial guess is "
      << apart * kRadToDeg << " deg from it\n";
  if (apart > allowed) {
    out << "  WARNING: the initial guess of R_b_m is " << apart * kRadToDeg
        << " deg from the mounting the drive shows (more than 3 sigma): check "
           "initial_calibration.q_b_m in dataset.yaml\n";
  }
}

// What giocal import says it converted (import.json next to dataset.yaml), or nothing.
std::string importedUnitNote(const std::string& folder) {
  std::ifstream in(folder + "/import.json");
  if (!in) return "";
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.contains("imu") || !j["imu"].contains("accel_unit")) return "";
  const std::string unit = j["imu"]["accel_unit"].get<std::string>();
  return unit == "m/s^2" ? "" : " (giocal import converted it from " + unit + ": import.json)";
}

}  // namespace

void runCheck(DatasetFolder& data, std::ostream& out) {
  const DatasetDescription& d = data.description;
  const std::string& folder = data.folder;
  out << "dataset " << folder << "\n";
  std::vector<std::string> warnings;
  const std::vector<ImuSample> imu = readImuCsv(d.pathOf(d.imu), &warnings);
  std::vector<OdomSample> odom = readOdomCsv(d.pathOf(d.odom), &warnings);
  if (!d.odom_noise.measures_yaw_rate && !imu.empty()) {
    // A speed-only odometer: the turn rate about gravity's axis stands for w, whatever the
    // mounting in dataset.yaml (which the mounting check below is to test).
    Eigen::Vector3d f = Eigen::Vector3d::Zero();
    for (const ImuSample& s : imu) f += s.acc;
    OdometerCalibration up;
    up.q_b_m = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), f.normalized());
    for (OdomSample& o : odom) o.w = gyroYawRate(imu, o.t, up);
  }
  printStats(out, d.imu, timesOf(imu));
  // imu.csv is m/s^2; a log in g or mg, or one whose force is gravity in no unit, is no use.
  const AccelUnit unit = accelUnitOf(imu);
  if (!unit.decided) throw std::runtime_error(accelUnitProblem(unit, d.pathOf(d.imu)));
  if (unit.name != "m/s^2") {
    throw std::runtime_error(d.pathOf(d.imu) + ": the mean specific force is " +
                             std::to_string(unit.mean_norm) + ": gravity in " + unit.name +
                             ", but imu.csv holds m/s^2 (multiply ax, ay, az by " +
                             std::to_string(unit.to_si) + "; giocal import converts bags)");
  }
  out << "            mean specific force " << std::setprecision(4) << unit.mean_norm << " m/s^2"
      << importedUnitNote(folder) << "\n";
  printStats(out, d.odom, timesOf(odom));
  if (!d.truth.empty()) printStats(out, d.truth, timesOf(readTruthCsv(d.pathOf(d.truth))));
  std::vector<std::string> missing;
  if (d.rover_obs.empty()) {
    out << "  no raw GNSS (files.rover_obs is empty): IMU and odometry only\n";
  }
  std::map<std::string, ObsData> gnss;
  for (const std::string& f : {d.rover_obs, d.base_obs}) {
    if (f.empty()) continue;
    if (std::count(data.missing.begin(), data.missing.end(), f)) {
      out << "  " << f << ": MISSING\n";
      missing.push_back(f);
      continue;
    }
    const ObsData& obs = gnss[f] = readRinexObs(d.pathOf(f));
    warnings.insert(warnings.end(), obs.warnings.begin(), obs.warnings.end());
    double sats = 0;
    for (const auto& e : obs.epochs) sats += static_cast<double>(e.sats.size());
    printStats(out, f, timesOf(obs.epochs));
    out << "            " << std::setprecision(1)
        << sats / std::max<double>(1.0, static_cast<double>(obs.epochs.size()))
        << " satellites per epoch (GPS, Galileo, BeiDou, QZSS)\n";
  }
  std::vector<NavData> navs;
  for (const std::string& f : d.nav) {
    if (std::count(data.missing.begin(), data.missing.end(), f)) {
      out << "  " << f << ": MISSING\n";
      missing.push_back(f);
      continue;
    }
    navs.push_back(readRinexNav(d.pathOf(f)));
    out << "  " << f << ": " << navs.back().ephemerides.size() << " broadcast ephemerides\n";
  }
  const auto& c = d.initial_calibration;
  const Vec3 rpy = rpyFromRotation(c.mean.q_b_m.toRotationMatrix()) * kRadToDeg;
  out << std::setprecision(4) << "  initial calibration: s_v " << c.mean.s_v << " s_w "
      << c.mean.s_w << " p_b_m [" << c.mean.p_b_m.transpose() << "] m, rpy_b_m [" << rpy.transpose()
      << "] deg\n";
  printMountingCheck(out, c, estimateMounting(imu, odom));
  for (const std::string& w : warnings) out << "  warning: " << w << "\n";
  std::vector<std::string> unusable;
  if (missing.empty() && gnss.count(d.rover_obs) && gnss.count(d.base_obs)) {
    const NavData nav = mergeNav(navs);
    unusable = diagnoseDataset({gnss.at(d.rover_obs), gnss.at(d.base_obs), nav, odom,
                                d.pathOf(d.rover_obs), d.pathOf(d.base_obs),
                                d.nav.empty() ? d.pathOf("dataset.yaml") : d.pathOf(d.nav.front()),
                                d.pathOf(d.odom)});
  }
  for (const std::string& u : unusable) out << "  unusable: " << u << "\n";
  for (const std::string& w : warnings) data.findings.push_back("warning: " + w);
  for (const std::string& u : unusable) data.findings.push_back("unusable: " + u);
  if (!unusable.empty()) {
    throw std::runtime_error("the dataset cannot be calibrated: " + unusable.front() +
                             (unusable.size() > 1
                                  ? " (and " + std::to_string(unusable.size() - 1) + " more above)"
                                  : std::string()));
  }
  if (!missing.empty()) {
    throw DataError(
        d.pathOf(missing.front()), 0,
        "file missing" + (missing.size() > 1
                              ? " (and " + std::to_string(missing.size() - 1) + " more GNSS files)"
                              : std::string()));
  }
}

}  // namespace giocal
