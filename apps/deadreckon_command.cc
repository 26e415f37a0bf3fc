#include "apps/deadreckon_command.h"

#include <filesystem>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <ostream>
#include <stdexcept>

#include "common/geodesy/wgs84.h"
#include "common/gnss/pos_reader.h"
#include "common/io/output_set.h"
#include "common/io/progress_line.h"
#include "common/math/rotation.h"
#include "evaluation/calibration_source.h"
#include "evaluation/dead_reckoning.h"
#include "options/giocal_config.h"
#include "replay/measured_heights.h"
#include "replay/run_preparation.h"

namespace giocal {
namespace {

const std::vector<std::string> kFiles{"trajectory.csv", "error.csv", "summary.json"};

nlohmann::ordered_json calibrationJson(const CalibrationPrior& c) {
  const Eigen::Quaterniond& q = c.mean.q_b_m;
  const Eigen::Vector3d rpy = rpyFromRotation(q.toRotationMatrix()) * kRadToDeg;
  return {{"s_v", c.mean.s_v},
          {"s_w", c.mean.s_w},
          {"p_b_m", {c.mean.p_b_m.x(), c.mean.p_b_m.y(), c.mean.p_b_m.z()}},
          {"q_b_m", {q.w(), q.x(), q.y(), q.z()}},
          {"rpy_b_m_deg", {rpy.x(), rpy.y(), rpy.z()}}};
}

}  // namespace

void runDeadReckon(const DeadReckonJob& job, std::ostream& log) {
  if (!job.overwrite) {
    for (const std::string& f : kFiles) {
      if (std::filesystem::exists(job.out + "/" + f)) {
        throw std::runtime_error(job.out + "/" + f + " exists; give --overwrite to replace it");
      }
    }
  }
  DeadReckoningJob dr;
  dr.options = readGiocalConfig(job.config).calibration;
  dr.start_s = job.start_s;
  dr.duration_s = job.duration_s;
  dr.options.loosely_coupled = !job.positions.empty();
  const DatasetFolder data = openDatasetFolder(job.data);  // once for the whole run
  CalibrationInputs in = loadCalibrationInputs(data, job.positions);
  // One receiver (asked, or a dataset without a base): its own track starts the aided part.
  dr.options.single_receiver = usesSingleReceiver(data.description, job.single, job.positions);
  if (dr.options.single_receiver) addSingleReceiverTrack(in, dr.options.single);
  checkStop(job.stop);
  // The GNSS-aided part weighs the solutions' heights as calibrate did.
  if (dr.options.loosely_coupled) applyFixHeights(measureFixHeights(in), dr.options);
  const CalibrationSource source = readCalibrationSource(job.calibration, in);
  applyCalibrationSource(source, dr, in.odom);
  std::string reference_path = job.reference;
  if (reference_path.empty()) {
    if (in.description.truth.empty()) {
      throw std::runtime_error(job.data +
                               " has no truth.csv: give --reference <trajectory.csv> (for example "
                               "a calibrate run's trajectory.csv)");
    }
    reference_path = in.description.pathOf(in.description.truth);
  }
  // A .pos reference (GNSS positions) has no attitude: the aided state at the start is kept.
  const bool pos_reference = std::filesystem::path(reference_path).extension() == ".pos";
  dr.reference_has_attitude = !pos_reference;
  const ReferenceTrajectory reference(pos_reference ? positionRows(readPosFile(reference_path))
                                                    : readTruthCsv(reference_path));
  ProgressLine progress("deadreckon", in.imu.front().t,
                        in.rover.epochs.front().t + job.start_s + job.duration_s, job.quiet);
  dr.progress = [&](double t) {
    progress.update(t);
    checkStop(job.stop);
  };
  const DeadReckoning r = deadReckon(in, reference, dr);
  progress.clear();
  checkStop(job.stop);

  OutputSet outputs(job.out);
  writeTruthCsv(outputs.stagedPath("trajectory.csv"), r.trajectory);
  std::ostream& err = outputs.open("error.csv");
  err << "t,elapsed_s,distance_m,east_m,north_m,up_m,horizontal_m\n" << std::setprecision(12);
  for (const DeadReckoningError& e : r.errors) {
    err << e.t << "," << e.elapsed << "," << e.distance << "," << e.enu.x() << "," << e.enu.y()
        << "," << e.enu.z() << "," << e.horizontal() << "\n";
  }
  nlohmann::ordered_json j;
  j["files"] = {{"trajectory.csv", outputs.close("trajectory.csv")},
                {"error.csv", outputs.close("error.csv")}};
  j["calibration_source"] = source.label;
  j["calibration"] = calibrationJson(source.calibration);
  if (source.odometer_delay_s != 0.0) j["odometer_delay_applied_s"] = source.odometer_delay_s;
  if (source.gyro_tilt.allFinite()) {
    j["gyro_tilt_applied_deg"] = {source.gyro_tilt.x() * kRadToDeg,
                                  source.gyro_tilt.y() * kRadToDeg};
  }
  j["reference"] = reference_path;
  j["gnss_before_start"] = !job.positions.empty()       ? "lc: " + job.positions
                           : dr.options.single_receiver ? std::string("single")
                                                        : std::string("tc");
  j["start_s"] = job.start_s;
  j["t_start"] = r.t_start;
  j["duration_s"] = r.t_end - r.t_start;
  j["gnss_aided_before_start_s"] = r.aided_s;
  j["horizontal_max_m"] = r.horizontal_max_m;
  j["horizontal_rmse_m"] = r.horizontal_rmse_m;
  j["distance_m"] = r.distance_m;
  j["final_error_m"] = r.final_error_m;
  j["final_error_percent_of_distance"] = r.final_error_percent_of_distance;
  outputs.open("summary.json", true) << std::setprecision(12) << j.dump(2) << "\n";
  outputs.commit();

  log << std::fixed << std::setprecision(2) << "giocal deadreckon: " << job.data << " with "
      << source.label << "\n  outage from +" << std::setprecision(1) << job.start_s << " s for "
      << r.t_end - r.t_start << " s (" << r.aided_s << " s GNSS-aided before), "
      << std::setprecision(1) << r.distance_m << " m driven\n  horizontal error: max "
      << std::setprecision(2) << r.horizontal_max_m << " m, RMSE " << r.horizontal_rmse_m
      << " m, final " << r.final_error_m << " m (" << r.final_error_percent_of_distance
      << " % of the distance)\n  outputs: " << job.out
      << "/{trajectory.csv, error.csv, summary.json}\n";
  for (const std::string& w : in.warnings) log << "  warning: " << w << "\n";
  log.unsetf(std::ios::fixed);
}

}  // namespace giocal
