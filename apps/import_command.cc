#include "apps/import_command.h"

#include <filesystem>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <ostream>
#include <stdexcept>

#include "apps/import_i2nav.h"
#include "common/calibration/coarse_mounting.h"
#include "common/gnss/broadcast_orbits.h"
#include "common/gnss/pos_file.h"
#include "common/gnss/rinex_nav_writer.h"
#include "common/gnss/rinex_obs_writer.h"
#include "common/gnss/spp.h"
#include "common/io/dataset_description.h"
#include "common/io/output_set.h"
#include "common/io/progress_line.h"
#include "common/io/sensor_logs.h"
#include "common/math/rotation.h"
#include "import/bag_dataset.h"
#include "import/ubx_log.h"

namespace giocal {

std::uintmax_t stageDatasetDescription(OutputSet& outputs, DatasetDescription& d) {
  d.folder = outputs.staging();
  outputs.stagedPath("dataset.yaml");  // joins the set; written by the dataset writer
  writeDatasetDescription(d);
  return outputs.close("dataset.yaml");
}

void refuseToOverwrite(const ImportJob& job, const std::vector<std::string>& files) {
  if (job.overwrite) return;
  for (const std::string& f : files) {
    if (std::filesystem::exists(job.out + "/" + f)) {
      throw std::runtime_error(job.out + "/" + f + " exists; give --overwrite to replace it");
    }
  }
}

namespace {

const std::vector<std::string> kUbxFiles{"rover.obs", "nav.rnx", "import.json"};
const std::vector<std::string> kBagFiles{"imu.csv", "odom.csv",     "gnss.pos",   "rover.obs",
                                         "nav.rnx", "dataset.yaml", "import.json"};

nlohmann::ordered_json countsJson(const import::TopicCounts& c) {
  return {{"topic", c.topic},
          {"type", c.type},
          {"read", c.read},
          {"out_of_order", c.out_of_order},
          {"non_finite", c.non_finite},
          {"no_fix", c.no_fix},
          {"largest_gap_s", c.largest_gap_s},
          {"times", c.record_times ? "record" : "header"}};
}

// Single point positions of the imported epochs: the check that observations and ephemerides
// fit together, and the header's approximate position.
struct SppCheck {
  int epochs = 0, solved = 0;
  Eigen::Vector3d first_p_e = Eigen::Vector3d::Zero();
};

SppCheck sppCheck(const import::UbxLog& log) {
  SppCheck c;
  const BroadcastOrbits orbits(log.nav);
  for (const ObsEpoch& e : log.obs.epochs) {
    ++c.epochs;
    const SppSolution s = solveSpp(e, orbits, SppOptions{});
    if (!s.valid) continue;
    if (c.solved++ == 0) c.first_p_e = s.p_e;
  }
  return c;
}

// Stages rover.obs and nav.rnx of a decoded UBX stream and returns what import.json says of it.
// `receiver` names what the observations came from; gnss_comm messages have no UBX frames.
nlohmann::ordered_json stageRawGnss(OutputSet& outputs, import::UbxLog& ubx,
                                    const std::string& receiver, std::ostream& log) {
  const bool gnss_comm = receiver == "gnss_comm";
  const SppCheck spp = sppCheck(ubx);
  RinexObsHeader header;
  header.program = "giocal import";
  header.marker = ubx.obs.header.marker;
  header.receiver = gnss_comm ? "gnss_comm (GnssMeasMsg)" : "u-blox (UBX-RXM-RAWX)";
  header.approx_position = spp.first_p_e;
  header.interval = ubx.obs.header.interval;
  header.obs_types = ubx.obs.header.obs_types;
  writeRinexObs(outputs.stagedPath("rover.obs"), header, ubx.obs.epochs);
  writeRinexNav(outputs.stagedPath("nav.rnx"), ubx.nav, "giocal import");
  std::map<std::string, int> per_system;
  for (const Ephemeris& e : ubx.nav.ephemerides)
    ++per_system[std::string(1, static_cast<char>(e.sat.sys))];
  nlohmann::ordered_json j;
  j["epochs"] = ubx.obs.epochs.size();
  j["t_first"] = ubx.obs.epochs.front().t;
  j["t_last"] = ubx.obs.epochs.back().t;
  j["interval_s"] = ubx.obs.header.interval;
  j["ephemerides"] = per_system;
  if (!gnss_comm) {
    j["frames"] = ubx.stream.frames;
    j["bad_checksums"] = ubx.stream.bad_checksums;
    j["skipped_bytes"] = ubx.stream.skipped_bytes;
    j["truncated_end"] = ubx.stream.truncated_end;
  }
  j[gnss_comm ? "measurements" : "rawx"] = {{"measurements", ubx.rawx.measurements},
                                            {"unsupported_system", ubx.rawx.unsupported_system},
                                            {"unknown_signal", ubx.rawx.unknown_signal},
                                            {"invalid_code", ubx.rawx.invalid_code},
                                            {"invalid_phase", ubx.rawx.invalid_phase},
                                            {"clock_resets", ubx.rawx.clock_resets},
                                            {"rejected_payloads", ubx.rawx_rejected},
                                            {"epochs_out_of_order", ubx.epochs_out_of_order}};
  j[gnss_comm ? "ephemeris_messages" : "subframes"] = {{"read", ubx.subframes},
                                                       {"rejected", ubx.subframes_rejected},
                                                       {"not_read", ubx.subframes_not_read}};
  if (!gnss_comm) j["other_messages"] = ubx.other_messages;
  j["spp_epochs_solved"] = spp.solved;
  log << "  raw GNSS: " << ubx.obs.epochs.size() << " epochs over " << std::fixed
      << std::setprecision(1) << ubx.obs.epochs.back().t - ubx.obs.epochs.front().t << " s, "
      << ubx.nav.ephemerides.size() << " ephemerides";
  for (const auto& [sys, n] : per_system) log << " " << sys << ":" << n;
  log << "; single point positions in " << spp.solved << " of " << spp.epochs << " epochs\n";
  log.unsetf(std::ios::fixed);
  return j;
}

void importUbx(const ImportJob& job, std::ostream& log) {
  refuseToOverwrite(job, kUbxFiles);
  ProgressLine progress("import", 0.0, 1.0, job.quiet, "of the file");
  import::UbxLog ubx = import::readUbxLog(job.ubx, [&](double share) {
    progress.update(share);
  checkStop(job.stop);
});
progress.clear();
checkStop(job.stop);
OutputSet outputs(job.out);
log << "giocal import: " << job.ubx << "\n";
nlohmann::ordered_json j;
const nlohmann::ordered_json gnss = stageRawGnss(outputs, ubx, "ubx", log);
j["files"] = {{"rover.obs", outputs.close("rover.obs")}, {"nav.rnx", outputs.close("nav.rnx")}};
j["source"] = job.ubx;
j.update(gnss);
j["warnings"] = ubx.warnings;
outputs.open("import.json", true) << std::setprecision(12) << j.dump(2) << "\n";
outputs.commit();
for (const std::string& w : ubx.warnings) log << "  warning: " << w << "\n";
log << "  outputs: " << job.out << "/{rover.obs, nav.rnx, import.json}\n";
}  // namespace

void importBag(const ImportJob& job, std::ostream& log) {
  refuseToOverwrite(job, kBagFiles);
  const auto bag = import::openBag(job.bag);
  ProgressLine progress("import", 0.0, 1.0, job.quiet, "of the messages");
  import::BagDataset d = import::readBagDataset(
      *bag, {job.imu_topic, job.odom_topic, job.fix_topic, import::stampSourceFromName(job.stamps)},
      [&](double share) {
        progress.update(share);
  checkStop(job.stop);
});
progress.clear();
checkStop(job.stop);
log << "giocal import: " << job.bag << "\n";

OutputSet outputs(job.out);
DatasetDescription desc;
desc.rover_obs = desc.base_obs = "";  // no raw GNSS in a bag of fixes
desc.nav.clear();
desc.imu_noise = d.imu_noise;
desc.odom_noise = d.odom_noise;
// The bag does not say how the IMU is mounted: the drive does (or the identity stays, 5 deg).
const CoarseMounting mounting = estimateMounting(d.imu, d.odom);
nlohmann::ordered_json mounting_json = {{"found_from_data", mounting.valid}};
if (mounting.valid) {
  desc.initial_calibration.mean.q_b_m = mounting.q_b_m;
  desc.initial_calibration.sd_rpy_b_m = mounting.sigma_rpy;
  const Eigen::Vector3d rpy = rpyFromRotation(mounting.q_b_m.toRotationMatrix()) * kRadToDeg;
  const Eigen::Vector3d sd = mounting.sigma_rpy * kRadToDeg;
  mounting_json["rpy_b_m_deg"] = {rpy.x(), rpy.y(), rpy.z()};
  mounting_json["sigma_deg"] = {sd.x(), sd.y(), sd.z()};
  mounting_json["yaw_rate_slope"] = mounting.yaw_rate_slope;
  log << std::fixed << std::setprecision(1) << "  mounting from the data: rpy_b_m [" << rpy.x()
      << ", " << rpy.y() << ", " << rpy.z() << "] deg, sigma [" << sd.x() << ", " << sd.y() << ", "
      << sd.z() << "] deg (the initial guess in dataset.yaml)\n";
  log.unsetf(std::ios::fixed);
} else {
  mounting_json["why_not"] = mounting.why_not;
  log << "  warning: mounting not found from the data (" << mounting.why_not
      << "): the initial guess is the identity; give it in dataset.yaml\n";
}
nlohmann::ordered_json raw_gnss;
if (d.raw_gnss) {
  raw_gnss = stageRawGnss(outputs, *d.raw_gnss, d.raw_gnss_source, log);
  desc.rover_obs = "rover.obs";  // no base station in a robot's bag: base_obs stays empty
  desc.nav = {"nav.rnx"};
}
writeImuCsv(outputs.stagedPath("imu.csv"), d.imu);
writeOdomCsv(outputs.stagedPath("odom.csv"), d.odom);
nlohmann::ordered_json files = {{"imu.csv", outputs.close("imu.csv")},
                                {"odom.csv", outputs.close("odom.csv")}};
if (d.raw_gnss) {
  files["rover.obs"] = outputs.close("rover.obs");
  files["nav.rnx"] = outputs.close("nav.rnx");
}
if (!d.fixes.empty()) {
  PosHeader h;
  h.program = "giocal import (sensor_msgs/NavSatFix of " + d.fix_counts.topic + ")";
  h.inputs = {job.bag};
  writePosFile(outputs.stagedPath("gnss.pos"), h, d.fixes);
  files["gnss.pos"] = outputs.close("gnss.pos");
}
files["dataset.yaml"] = stageDatasetDescription(outputs, desc);
nlohmann::ordered_json j;
j["files"] = files;
j["source"] = job.bag;
j["imu"] = countsJson(d.imu_counts);
j["imu"]["accel_unit"] = d.imu_accel_unit;  // as the bag had it; imu.csv is in m/s^2
j["odometry"] = countsJson(d.odom_counts);
if (!d.fix_counts.topic.empty()) j["fix"] = countsJson(d.fix_counts);
if (d.raw_gnss) {
  raw_gnss["messages"] = d.raw_gnss_source;
  raw_gnss["topics"] = {d.raw_observation_topic, d.raw_ephemeris_topic};
  j["raw_gnss"] = raw_gnss;
}
j["utc_stamps"] = d.utc_stamps;
j["leap_seconds"] = d.leap_seconds;
j["noise_sources"] = d.noise_sources;
j["mounting"] = mounting_json;
j["warnings"] = d.warnings;
outputs.open("import.json", true) << std::setprecision(12) << j.dump(2) << "\n";
outputs.commit();

log << "  " << d.imu.size() << " IMU samples (" << d.imu_counts.topic << "), " << d.odom.size()
    << " odometry samples (" << d.odom_counts.topic << ")";
if (!d.fixes.empty()) log << ", " << d.fixes.size() << " GNSS fixes (" << d.fix_counts.topic << ")";
log << std::fixed << std::setprecision(1) << " over " << d.imu.back().t - d.imu.front().t << " s\n";
for (const std::string& n : d.noise_sources) log << "  noise: " << n << "\n";
for (const std::string& w : d.warnings) log << "  warning: " << w << "\n";
log << "  outputs: " << job.out << "/{imu.csv, odom.csv, " << (d.fixes.empty() ? "" : "gnss.pos, ")
    << (d.raw_gnss ? "rover.obs, nav.rnx, " : "") << "dataset.yaml, import.json}\n";
log.unsetf(std::ios::fixed);
}  // namespace giocal

}  // namespace

void runImport(const ImportJob& job, std::ostream& log) {
  const int sources = !job.ubx.empty() + !job.bag.empty() + !job.i2nav_imu.empty();
  if (sources != 1) throw std::runtime_error("give one of --ubx, --bag and --i2nav-imu");
  if (!job.ubx.empty()) {
    importUbx(job, log);
  } else if (!job.bag.empty()) {
    importBag(job, log);
  } else {
    importI2nav(job, log);
  }
}

}  // namespace giocal
