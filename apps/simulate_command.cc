#include "apps/simulate_command.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "common/geodesy/wgs84.h"
#include "common/gnss/broadcast_orbits.h"
#include "common/gnss/pos_reader.h"
#include "common/gnss/rinex_nav.h"
#include "common/gnss/rinex_obs.h"
#include "common/gnss/rinex_obs_writer.h"
#include "common/io/dataset_description.h"
#include "common/io/output_set.h"
#include "common/math/rotation.h"
#if GIOCAL_FACTOR_GRAPH
#include "sim/fitted_path.h"
#endif
#include "sim/moved_rover.h"
#include "sim/simulator.h"
#include "sim/trajectory.h"

namespace giocal {

namespace {

void refuseDatasetFolder(const std::string& out) {
  for (const char* f : {"dataset.yaml", "imu.csv", "odom.csv", "truth.csv", "truth_calib.yaml"}) {
    if (std::filesystem::exists(std::filesystem::path(out) / f)) {
      throw std::runtime_error(out + ": already holds a dataset (" + f +
                               "); choose an empty folder or remove it first");
    }
  }
}

// A copy in the staged dataset that belongs to the user (the source may be read-only).
void copyInto(OutputSet& outputs, const std::string& from, const std::string& name) {
  std::filesystem::copy_file(from, outputs.stagedPath(name));
  std::filesystem::permissions(outputs.stagedPath(name), std::filesystem::perms::owner_write,
                               std::filesystem::perm_options::add);
}

std::vector<std::string> navNames(size_t n) {
  std::vector<std::string> names;
  for (size_t k = 0; k < n; ++k)
    names.push_back(k == 0 ? "nav.rnx" : "nav" + std::to_string(k + 1) + ".rnx");
  return names;
}

void requireFiles(const std::vector<std::string>& files) {
  for (const std::string& f : files) {
    if (!std::filesystem::is_regular_file(f)) throw std::runtime_error(f + ": file missing");
  }
}

/// Before a run on given GNSS files: `out` is not a dataset already, navigation is given, and
/// the rover, the base (empty: a rover alone) and the navigation files exist.
void checkGnssRun(const std::string& out, const std::string& rover, const std::string& base,
                  const std::vector<std::string>& nav) {
  refuseDatasetFolder(out);
  if (nav.empty()) throw std::runtime_error("give the navigation file(s) with --nav");
  std::vector<std::string> given{rover};
  if (!base.empty()) given.push_back(base);
  given.insert(given.end(), nav.begin(), nav.end());
  requireFiles(given);
}

/// The base (empty: none) and navigation files copied in under their names in `d`, then the
/// dataset committed (unless a stop was asked for).
void finishGnssDataset(OutputSet& outputs, const DatasetDescription& d, const std::string& base,
                       const std::vector<std::string>& nav, const StopRequest* stop) {
  if (!base.empty()) copyInto(outputs, base, d.base_obs);
  for (size_t k = 0; k < nav.size(); ++k) copyInto(outputs, nav[k], d.nav[k]);
  checkStop(stop);
  outputs.commit();
}

}  // namespace

void runSimulate(const std::string& config, const std::string& out, std::uint64_t seed,
                 std::ostream& log, const StopRequest* stop, bool no_base) {
  sim::SimConfig cfg = sim::readSimConfig(config);
  if (no_base && cfg.gnss.enabled && cfg.gnss.base) {
    cfg.gnss.base = false;
    sim::setSingleReceiverDefaults(cfg.gnss);
  }
  refuseDatasetFolder(out);
  const auto start = std::chrono::steady_clock::now();
  const sim::SimulatedLogs logs = sim::simulate(cfg, seed);
  checkStop(stop);
  // The dataset appears whole or not at all; dataset.yaml, which names the others, goes last.
  OutputSet outputs(out);
  outputs.stagedPath("dataset.yaml", true);
  sim::writeDataset(logs, outputs.staging());
  checkStop(stop);
  outputs.commit();
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  log << "simulated '" << cfg.name << "' (seed " << seed
      << "): " << logs.truth.back().t - logs.truth.front().t << " s, " << logs.imu.size()
      << " IMU and " << logs.odom.size() << " odometer samples, " << logs.gnss.rover.size()
      << " GNSS epochs" << (cfg.gnss.base ? "" : " (a rover alone)") << " in " << wall << " s -> "
      << out << "\n";
  if (!cfg.gnss.base) {
    log << "  rover alone: " << logs.gnss.slips << " slips (" << logs.gnss.half_cycles
        << " half cycles), " << logs.gnss.clock_steps << " receiver clock steps\n";
  }
  if (logs.gnss.rover.empty()) log << "note: the config has no gnss section; no RINEX written\n";
}

void runSimulateAlong(const std::string& config, const GivenGnss& gnss, const std::string& out,
                      std::uint64_t seed, std::ostream& log, const StopRequest* stop) {
#if !GIOCAL_FACTOR_GRAPH
  (void)config, (void)gnss, (void)out, (void)seed, (void)log, (void)stop;
  throw std::runtime_error(
      "simulate --trajectory: this giocal was built without the factor graph "
      "(-DGIOCAL_FACTOR_GRAPH=OFF), whose solver fits the path");
#else
  const sim::SimConfig cfg = sim::readSimConfig(config);
  checkGnssRun(out, gnss.rover, gnss.base, gnss.nav);
  // Fixed and float solutions; single points are metres off a vehicle's path.
  std::vector<PositionFix> fixes;
  long left_out = 0;
  std::vector<std::string> repaired;
  const std::vector<PositionFix> solutions = readPosFile(gnss.trajectory, &repaired);
  for (const std::string& w : repaired) log << "  warning: " << w << "\n";
  for (const PositionFix& f : solutions) {
    if (f.quality == 1 || f.quality == 2) {
      fixes.push_back(f);
    } else {
      ++left_out;
    }
  }
  if (fixes.size() < 10) {
    throw std::runtime_error(gnss.trajectory + ": fewer than 10 fixed or float solutions");
  }
  const LocalFrame frame(fixes.front().p_e);
  const double t0 = fixes.front().t;
  std::vector<sim::AntennaFix> path_fixes;
  for (const PositionFix& f : fixes) {
    path_fixes.push_back(
        {f.t - t0, frame.enuFromEcef(f.p_e), f.cov_enu.diagonal().cwiseMax(0.0).cwiseSqrt()});
  }
  // The antenna in m: p_m_g = R_m_b (p_b_g - p_b_m).
  const Eigen::Matrix3d R_m_b = cfg.truth.q_b_m.toRotationMatrix().transpose();
  const auto start = std::chrono::steady_clock::now();
  // Knots every two solution intervals by default: closer knots follow the solution's noise
  // (docs/results.md, "Real GNSS with synthesized motion sensors").
  sim::FittedPathOptions po;
  std::vector<double> dts;
  for (size_t k = 1; k < path_fixes.size(); ++k)
    dts.push_back(path_fixes[k].t - path_fixes[k - 1].t);
  std::nth_element(dts.begin(), dts.begin() + static_cast<long>(dts.size() / 2), dts.end());
  po.knot_spacing =
      gnss.knot_spacing > 0.0 ? gnss.knot_spacing : std::max(0.5, 2.0 * dts[dts.size() / 2]);
  const sim::FittedPath path(path_fixes, R_m_b * (cfg.p_b_g - cfg.truth.p_b_m), po);
  checkStop(stop);
  sim::SimulatedLogs logs = sim::simulateMotionSensors(cfg, path, frame, t0, seed);
  checkStop(stop);
  DatasetDescription& d = logs.description;
  d.nav = navNames(gnss.nav.size());
  if (gnss.base.empty()) d.base_obs.clear();  // a rover alone
  OutputSet outputs(out);
  outputs.stagedPath("dataset.yaml", true);
  sim::writeDataset(logs, outputs.staging());
  copyInto(outputs, gnss.rover, d.rover_obs);
  finishGnssDataset(outputs, d, gnss.base, gnss.nav, stop);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  log << std::fixed << std::setprecision(3) << "simulated '" << cfg.name
      << "' motion sensors (seed " << seed << ") along " << gnss.trajectory << ": "
      << path.duration() << " s, " << logs.imu.size() << " IMU and " << logs.odom.size()
      << " odometer samples, knots every " << po.knot_spacing << " s; the path's "
      << "antenna against the " << fixes.size() << " solutions: median " << path.medianMiss()
      << " m, max " << path.maxMiss() << " m, " << path.outliers()
      << " more than 5 sigma off and left aside (" << left_out
      << " single or other solutions not used); " << wall << " s -> " << out << "\n";
  log.unsetf(std::ios::fixed);
  if (path.medianMiss() > 0.05) {
    log << "warning: the path misses the solutions by " << path.medianMiss()
        << " m (median): the real carrier phases will not fit the synthesized motion to their "
           "noise (a solution with jumps, or motion a ground vehicle cannot make)\n";
  }
#endif
}

void runSimulateMoved(const std::string& config, const MovedGnss& gnss, const std::string& out,
                      std::uint64_t seed, std::ostream& log, const StopRequest* stop) {
  const sim::SimConfig cfg = sim::readSimConfig(config);
  checkGnssRun(out, gnss.rover, gnss.base, gnss.nav);
  const auto start = std::chrono::steady_clock::now();
  const ObsData rover = readRinexObs(gnss.rover);
  for (const std::string& w : rover.warnings)
    log << "  warning: " << gnss.rover << ": " << w << "\n";
  std::vector<NavData> parts;
  for (const std::string& f : gnss.nav) parts.push_back(readRinexNav(f));
  const BroadcastOrbits orbits(mergeNav(parts));
  const sim::Trajectory drive(sim::MotionProfile(cfg.segments), cfg.terrain,
                              Eigen::Vector3d::Zero(), cfg.initial_heading_deg * kDegToRad);
  if (rover.epochs.size() < 2) throw std::runtime_error(gnss.rover + ": fewer than 2 epochs");
  const double t0 = std::ceil(rover.epochs.front().t - 1e-6);
  const double covered = rover.epochs.back().t - t0;
  if (covered < drive.duration()) {
    std::ostringstream msg;
    msg << gnss.rover << ": " << covered << " s of observations from its first whole second, "
        << "and the preset's drive takes " << drive.duration() << " s";
    throw std::runtime_error(msg.str());
  }
  const LocalFrame frame(gnss.rover_pos);
  sim::SimulatedLogs logs = sim::simulateMotionSensors(cfg, drive, frame, t0, seed);
  checkStop(stop);
  const sim::MovedRover moved =
      sim::moveStaticRover(rover.epochs, orbits, gnss.rover_pos,
                           sim::antennaPath(cfg, drive, frame, t0), t0, t0 + drive.duration());
  checkStop(stop);
  DatasetDescription& d = logs.description;
  d.nav = navNames(gnss.nav.size());
  if (gnss.base.empty()) d.base_obs.clear();  // a rover alone
  d.base_position_ecef = gnss.base_pos;
  OutputSet outputs(out);
  outputs.stagedPath("dataset.yaml", true);
  sim::writeDataset(logs, outputs.staging());
  RinexObsHeader h;
  h.program = "giocal simulate";
  h.marker = rover.header.marker.empty() ? "ROVER" : rover.header.marker;
  h.receiver = "REAL, MOVED";
  h.antenna = "REAL";
  Eigen::Vector3d v;
  sim::antennaPath(cfg, drive, frame, t0)(t0, h.approx_position, v);
  h.interval = rover.header.interval;
  // The codes of the signals moved (a system or band without a carrier frequency is left out).
  for (const auto& [sys, codes] : rover.header.obs_types) {
    for (const std::string& c : codes) {
      if (c.size() == 3 && carrierFrequency(static_cast<GnssSystem>(sys), c[1]) > 0.0)
        h.obs_types[sys].push_back(c);
    }
  }
  writeRinexObs(outputs.stagedPath(d.rover_obs), h, moved.epochs);
  finishGnssDataset(outputs, d, gnss.base, gnss.nav, stop);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  log << std::fixed << std::setprecision(3) << "simulated '" << cfg.name
      << "' motion sensors (seed " << seed << ") and moved " << gnss.rover
      << " along the drive: " << drive.duration() << " s from its first whole second, "
      << moved.epochs.size() << " epochs, " << moved.signals
      << " signals moved (ranges changed by up to " << moved.max_move << " m), "
      << moved.unsupported_signals
      << " signals of systems or bands without a carrier frequency and " << moved.no_ephemeris
      << " satellite epochs without an ephemeris left out; " << wall << " s -> " << out << "\n";
  log.unsetf(std::ios::fixed);
}

}  // namespace giocal
