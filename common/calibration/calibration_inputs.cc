#include "common/calibration/calibration_inputs.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "common/gnss/rinex_obs.h"
#include "common/gnss/tdcp_track.h"
#include "common/io/data_error.h"
#include "common/io/sensor_logs.h"
#include "common/odometer/gyro_yaw_rate.h"

namespace giocal {

double CalibrationInputs::dataDuration() const {
  if (imu.empty() || rover.epochs.empty()) return 0.0;
  const double t0 = std::max(imu.front().t, rover.epochs.front().t);
  const double t1 = std::min(imu.back().t, rover.epochs.back().t);
  return std::max(0.0, t1 - t0);
}

CalibrationInputs loadCalibrationInputs(const std::string& folder, const std::string& positions) {
  return loadCalibrationInputs(openDatasetFolder(folder), positions);
}

CalibrationInputs loadCalibrationInputs(const DatasetFolder& data, const std::string& positions) {
  CalibrationInputs in;
  in.description = data.description;
  const DatasetDescription& d = in.description;
  auto need = [&](const std::string& name) {
    const std::string p = d.pathOf(name);
    if (!std::filesystem::exists(p)) throw DataError(p, 0, "file missing");
    return p;
  };
  in.imu = readImuCsv(need(d.imu), &in.warnings);
  in.odom = readOdomCsv(need(d.odom), &in.warnings);
  for (ImuSample& s : in.imu) s.t += d.time_offsets.imu;
  for (OdomSample& s : in.odom) s.t += d.time_offsets.odometer;
  if (in.imu.size() < 2) throw DataError(d.pathOf(d.imu), 0, "fewer than two IMU samples");
  if (in.odom.empty()) throw DataError(d.pathOf(d.odom), 0, "no odometer samples");
  if (!d.odom_noise.measures_yaw_rate) {
    // A speed-only odometer turns with the gyro (as the online calibrator's samples do).
    for (OdomSample& s : in.odom) s.w = gyroYawRate(in.imu, s.t, d.initial_calibration.mean);
  }
  in.truth = data.truth;
  if (!positions.empty()) {
    in.positions = readPosFile(positions, &in.warnings);
    if (in.positions.empty()) throw DataError(positions, 0, "no position solutions");
    for (PositionFix& p : in.positions) p.t += d.time_offsets.positions;
  }
  if (d.rover_obs.empty() && !in.positions.empty()) {
    for (const PositionFix& p : in.positions) {
      ObsEpoch e;
      e.t = p.t;
      in.rover.epochs.push_back(e);
    }
    for (const std::string& n : d.nav) in.nav = mergeNav({in.nav, readRinexNav(need(n))});
    in.base_e = in.positions.front().p_e;
    if (in.dataDuration() <= 0.0) {
      throw DataError(d.pathOf(d.imu), 0, "the IMU log and the position solutions do not overlap");
    }
    return in;
  }
  if (d.roverAlone()) {
    // A rover alone (the single-receiver scheme): the origin is its first single point position,
    // the track for the initial heading is the caller's (singleReceiverTrack).
    in.rover = readRinexObs(need(d.rover_obs));
    in.warnings.insert(in.warnings.end(), in.rover.warnings.begin(), in.rover.warnings.end());
    if (in.rover.epochs.empty()) throw DataError(d.pathOf(d.rover_obs), 0, "no epochs");
    std::vector<NavData> navs;
    for (const std::string& n : d.nav) navs.push_back(readRinexNav(need(n)));
    in.nav = mergeNav(navs);
    if (in.dataDuration() <= 0.0) {
      throw DataError(d.pathOf(d.imu), 0, "the IMU log and the rover observations do not overlap");
    }
    return in;
  }
  requireRawGnss(d);
  in.rover = readRinexObs(need(d.rover_obs));
  in.base = readRinexObs(need(d.base_obs));
  for (const auto* obs : {&in.rover, &in.base}) {
    in.warnings.insert(in.warnings.end(), obs->warnings.begin(), obs->warnings.end());
  }
  if (in.rover.epochs.empty()) throw DataError(d.pathOf(d.rover_obs), 0, "no epochs");
  if (in.base.epochs.empty()) throw DataError(d.pathOf(d.base_obs), 0, "no epochs");
  std::vector<NavData> navs;
  for (const std::string& n : d.nav) navs.push_back(readRinexNav(need(n)));
  in.nav = mergeNav(navs);
  in.base_e = d.base_position_ecef ? *d.base_position_ecef : in.base.header.approx_position;
  if (in.base_e.norm() < 6.0e6) {
    throw DataError(d.pathOf(d.base_obs), 0,
                    "no APPROX POSITION XYZ in the header; give gnss.base_position_ecef in "
                    "dataset.yaml");
  }
  if (in.dataDuration() <= 0.0) {
    throw DataError(d.pathOf(d.imu), 0, "the IMU log and the rover observations do not overlap");
  }
  return in;
}

void addSingleReceiverTrack(CalibrationInputs& in, const SingleReceiverOptions& options) {
  const BroadcastOrbits orbits(in.nav);
  TdcpTrack track(orbits, options.tdcp, options.position_sigma_min_m);
  in.positions.clear();
  in.track_restarts.clear();
  for (const ObsEpoch& e : in.rover.epochs) {
    const std::optional<PositionFix> fix = track.add(e);
    if (!fix) continue;
    if (track.startedStretch() && !in.positions.empty())
      in.track_restarts.push_back(in.positions.size());
    in.positions.push_back(*fix);
  }
  if (in.positions.empty()) {
    throw std::runtime_error(
        "no single point position of the rover (do the navigation files "
        "cover its observations?)");
  }
  in.base_e = in.positions.front().p_e;
}

}  // namespace giocal
