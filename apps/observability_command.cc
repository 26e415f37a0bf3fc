#include "apps/observability_command.h"

#include <filesystem>
#include <iomanip>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>
#include <stdexcept>

#include "apps/dataset_rtk.h"
#include "common/calibration/weak_directions.h"
#include "common/gnss/rtk_job.h"
#include "common/io/dataset_description.h"
#include "common/io/output_set.h"
#include "common/io/sensor_logs.h"
#include "common/io/text.h"
#include "common/math/median.h"
#include "evaluation/observability.h"
#include "options/giocal_config.h"

namespace giocal {
namespace {

std::string motionText(const DriveMotion& m) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(0) << std::setw(6) << m.distance_m << " m  turns L "
    << std::setw(4) << m.turned_left_deg << " R " << std::setw(4) << m.turned_right_deg
    << " deg  dv " << std::setprecision(1) << std::setw(4) << m.speed_change_m_s << " m/s  still "
    << std::setprecision(0) << std::setw(3) << m.still_s << " s";
  return s.str();
}

nlohmann::ordered_json sigmaJson(const Eigen::Matrix<double, 8, 1>& s) {
  nlohmann::ordered_json j;
  for (int k = 0; k < 8; ++k) j[calibrationStateName(k)] = s[k];
  return j;
}

}  // namespace

void runObservability(const ObservabilityCommandJob& job, std::ostream& log) {
  if (!(job.position_sigma_m >= 0.0) || !(job.window_s > 0.0)) {
    throw std::runtime_error("--position-sigma must be 0 or more and --window positive");
  }
  const std::string json = job.out.empty() ? "" : job.out + "/observability.json";
  if (job.gnss != "tc" && job.gnss != "single")
    throw std::runtime_error("--gnss must be tc or single, not '" + job.gnss + "'");
  if (job.gnss == "single" && !job.positions.empty()) {
    throw std::runtime_error(
        "--pos and --gnss single do not go together: one receiver's own "
        "carrier phase gives the GNSS of the analysis");
  }
  if (!json.empty() && std::filesystem::exists(json) && !job.overwrite) {
    throw std::runtime_error(json + " exists; give --overwrite to replace it");
  }
  const auto config = readGiocalConfig(job.config);
  // Without a truth or a given solution, the drive's motion comes from giocal rtk's solution.
  std::string positions = job.positions;
  std::unique_ptr<TempPosFile> own_rtk;
  const DatasetFolder data = openDatasetFolder(job.data);  // once for the whole run
  const DatasetDescription& d = data.description;
  // One receiver: its own TDCP, Doppler and single point positions are the GNSS, no solution.
  const bool single = job.gnss == "single" || (positions.empty() && d.roverAlone());
  if (single && job.position_sigma_m > 0.0) {
    throw std::runtime_error("--position-sigma makes antenna positions: not with one receiver");
  }
  if (positions.empty() && d.truth.empty() && !single) {
    requireRawGnss(d);
    own_rtk = std::make_unique<TempPosFile>("observability");
    positions = own_rtk->path;
    runRtk(datasetRtkJob(d, config, positions));
  }
  CalibrationInputs in = loadCalibrationInputs(data, positions);
  if (single) addSingleReceiverTrack(in, config.calibration.single);
  ObservabilityJob oj;
  oj.options = config.calibration;
  oj.options.single_receiver = single;
  oj.window_s = job.window_s;
  const std::string calibration =
      !job.calibration.empty() ? job.calibration : (in.truth ? "truth" : "guess");
  if (calibration == "truth") {
    if (!in.truth)
      throw std::runtime_error(job.data + " has no truth_calib.yaml: use --calibration guess");
    oj.linearize_at = in.truth->calib;
  } else if (calibration == "guess") {
    oj.linearize_at = in.description.initial_calibration.mean;
  } else {
    throw std::runtime_error("--calibration must be truth or guess, not '" + calibration + "'");
  }
  std::string reference = (single    ? std::string("the rover alone")
                           : own_rtk ? "giocal rtk's solution"
                                     : "--pos " + job.positions) +
                          " (linearized at the filter's own estimate)";
  if (single) {
    if (d.truth.empty()) {
      log << "  dataset.yaml names no truth: the filter runs on its own estimate\n";
    } else {
      oj.reference = ReferenceTrajectory(readTruthCsv(in.description.pathOf(in.description.truth)));
      reference =
          "truth.csv, with one receiver's time-differenced carrier phase, Doppler and single "
          "point positions";
    }
  } else if (positions.empty()) {
    oj.reference = ReferenceTrajectory(readTruthCsv(in.description.pathOf(in.description.truth)));
    const Eigen::Vector3d p_b_g = in.truth ? in.truth->p_b_g : in.description.p_b_g;
    if (job.position_sigma_m > 0.0) {
      std::vector<double> times;
      for (const ObsEpoch& e : in.rover.epochs) times.push_back(e.t);
      in.positions = antennaPositionsAlong(*oj.reference, p_b_g, times, job.position_sigma_m);
      reference =
          "truth.csv, antenna positions with " + fixedText(job.position_sigma_m, 3) + " m sigma";
    } else {
      // What a fixed epoch's DD phase tells of the antenna, with the satellites it saw.
      in.positions = antennaPositionsFromPhase(*oj.reference, p_b_g, in, oj.options);
      if (in.positions.empty()) {
        throw std::runtime_error(job.data +
                                 ": no rover epoch with a base epoch and four satellites "
                                 "to fix: give --position-sigma");
      }
      std::vector<double> east, north, up;
      for (const PositionFix& f : in.positions) {
        east.push_back(std::sqrt(f.cov_enu(0, 0)));
        north.push_back(std::sqrt(f.cov_enu(1, 1)));
        up.push_back(std::sqrt(f.cov_enu(2, 2)));
      }
      reference =
          "truth.csv, antenna positions with the sigma of each epoch's fixed DD phase "
          "(median E/N/U " +
          fixedText(1e3 * median(east), 1) + "/" + fixedText(1e3 * median(north), 1) + "/" +
          fixedText(1e3 * median(up), 1) + " mm, " + std::to_string(in.positions.size()) +
          " epochs)";
    }
  }
  const ObservabilityReport r = analyzeObservability(in, oj);

  log << "giocal observability: " << job.data << "\n  motion from " << reference << "; calibration "
      << (oj.reference ? "held at" : "started from") << " the " << calibration << "\n"
      << "  window [s]    motion in it (odometer, uncalibrated)              expected 1-sigma at "
         "its end:\n"
      << std::string(70, ' ') << "s_v      s_w      x [m]  y [m]  z [m]  roll   pitch  yaw [deg]\n";
  for (const ObservabilityWindow& w : r.windows) {
    log << "  " << std::fixed << std::setprecision(0) << std::setw(5) << w.t0 << "-" << std::left
        << std::setw(6) << w.t1 << std::right << "  " << motionText(w.motion) << "  ";
    for (int k = 0; k < 8; ++k) {
      log << std::setprecision(k < 2 ? 5 : (k < 5 ? 3 : 2)) << std::left << std::setw(k < 2 ? 9 : 7)
          << w.sigma[k] << std::right;
    }
    log << "\n";
  }
  log.unsetf(std::ios::fixed);
  log << std::setprecision(3) << "  state            prior       expected    (unit)\n";
  for (int k = 0; k < 8; ++k) {
    if (k == r.vertical_state) {
      log << "  " << std::left << std::setw(15) << calibrationStateName(k) << std::right << " "
          << std::setw(10) << r.prior_sigma[k] << "  " << std::setw(10) << r.p_b_m_z_sigma_free
          << "   m  "
          << (!r.p_b_m_z_assessed    ? "not assessed without truth.csv"
              : r.p_b_m_z_observable ? "observable"
                                     : "UNOBSERVABLE (planar motion)")
          << " (along the vehicle's vertical, were it estimated)\n";
      continue;
    }
    log << "  " << std::left << std::setw(15) << calibrationStateName(k) << std::right << " "
        << std::setw(10) << r.prior_sigma[k] << "  " << std::setw(10) << r.expected_sigma[k] << "  "
        << calibrationStateUnit(k) << "\n";
  }
  for (int k : r.weak) log << "  weakly observed: " << calibrationStateName(k) << "\n";
  for (const std::string& c : r.couplings) log << "  coupled: " << c << "\n";
  for (const std::string& a : r.advice) log << "  advice: " << a << "\n";

  if (json.empty()) return;
  nlohmann::ordered_json j;
  j["data"] = job.data;
  j["reference"] = reference;
  j["linearized_at"] = calibration;
  j["prior_sigma"] = sigmaJson(r.prior_sigma);
  j["expected_sigma"] = sigmaJson(r.expected_sigma);
  j["p_b_m_z"] = {{"sigma_if_estimated", r.p_b_m_z_sigma_free},
                  {"observable", r.p_b_m_z_observable},
                  {"assessed", r.p_b_m_z_assessed}};
  std::vector<std::string> weak;
  for (int k : r.weak) weak.push_back(calibrationStateName(k));
  j["weak"] = weak;
  j["couplings"] = r.couplings;
  j["advice"] = r.advice;
  for (const ObservabilityWindow& w : r.windows) {
    j["windows"].push_back({{"t0", w.t0},
                            {"t1", w.t1},
                            {"distance_m", w.motion.distance_m},
                            {"turned_left_deg", w.motion.turned_left_deg},
                            {"turned_right_deg", w.motion.turned_right_deg},
                            {"speed_change_m_s", w.motion.speed_change_m_s},
                            {"still_s", w.motion.still_s},
                            {"sigma", sigmaJson(w.sigma)},
                            {"information_over_prior", sigmaJson(w.information)}});
  }
  OutputSet outputs(job.out);
  outputs.open("observability.json", true) << std::setprecision(12) << j.dump(2) << "\n";
  outputs.commit();
  log << "  -> " << json << "\n";
}

}  // namespace giocal
