#include "apps/compare_command.h"

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "apps/live_run_writer.h"
#include "common/calibration/fix_audit.h"
#include "common/math/rotation.h"
#include "options/giocal_config.h"
#include "replay/replay.h"
#include "replay/run_preparation.h"

namespace giocal {
namespace {

struct Row {
  std::string name;
  double value[2], sd[2], error[2];
};

}  // namespace

bool runCompare(const CompareJob& job, std::ostream& log) {
  const std::string out = job.out.empty() ? job.data + "/giocal_compare" : job.out;
  const std::vector<std::string> files{"compare.csv", "ekf/summary.json", "fgo/summary.json"};
  if (!job.overwrite) {
    for (const std::string& f : files) {
      if (std::filesystem::exists(out + "/" + f)) {
        throw std::runtime_error(out + "/" + f + " exists; give --overwrite to replace it");
      }
    }
  }
  ReplayJob replay;
  const GiocalConfig config = readGiocalConfig(job.config);
  replay.options = config.calibration;
  replay.fgo_options = config.fgo;
  replay.options_in_effect = config.in_effect;
  replay.positions = job.positions;
  replay.options.loosely_coupled = !job.positions.empty();
  replay.stop = job.stop;
  DatasetFolder data = openDatasetFolder(job.data);  // once for both runs
  chooseSingleReceiver(data.description, job.single, replay, log);
  // The odometer's delay and the solutions' heights, measured and acted on as calibrate does.
  const RunPreparation prepared = prepareRun(data, replay, log);
  OutputSet outputs(out);
  const std::optional<TruthCalibration>& truth_file = data.truth;
  const OdometerCalibration* truth = truth_file ? &truth_file->calib : nullptr;
  CalibrationRun runs[2];
  const char* estimators[2] = {"ekf", "fgo"};
  const auto span = data.imu_span;
  for (int a = 0; a < 2; ++a) {
    replay.estimator = estimators[a];
    ProgressLine progress(std::string("compare ") + estimators[a], span.first, span.second,
                          job.quiet);
    LiveRunWriter writer(outputs, std::string(estimators[a]) + "/", estimators[a], log, &progress);
    const std::unique_ptr<FixAudit> audit = fixAuditOf(data, &writer);
    runs[a] =
        replayCheckingPositions(data, replay, audit ? static_cast<RunSink*>(audit.get()) : &writer);
    if (audit) audit->addTo(runs[a]);
    progress.clear();
    notePreparation(prepared, data, runs[a]);
    writer.finish(runs[a], truth);
  }

  std::vector<Row> rows;
  const char* names[8] = {"s_v",         "s_w",        "p_b_m.x [m]", "p_b_m.y [m]",
                          "p_b_m.z [m]", "roll [deg]", "pitch [deg]", "yaw [deg]"};
  for (int i = 0; i < 8; ++i) rows.push_back({names[i], {}, {}, {}});
  for (int a = 0; a < 2; ++a) {
    const CalibrationEstimate& e = runs[a].final();
    const Eigen::Vector3d rpy = rpyFromRotation(e.calib.q_b_m.toRotationMatrix()) * kRadToDeg;
    const Eigen::Matrix<double, 8, 1> sd = e.sigma();
    const double v[8] = {e.calib.s_v,       e.calib.s_w, e.calib.p_b_m.x(), e.calib.p_b_m.y(),
                         e.calib.p_b_m.z(), rpy.x(),     rpy.y(),           rpy.z()};
    for (int i = 0; i < 8; ++i) {
      rows[static_cast<size_t>(i)].value[a] = v[i];
      rows[static_cast<size_t>(i)].sd[a] = sd[i];
      rows[static_cast<size_t>(i)].error[a] = NAN;
    }
    if (truth) {
      const CalibrationError err = calibrationError(e, *truth);
      const double d[8] = {err.s_v,
                           err.s_w,
                           err.p_b_m.x(),
                           err.p_b_m.y(),
                           err.p_b_m.z(),
                           err.rpy.x() * kRadToDeg,
                           err.rpy.y() * kRadToDeg,
                           err.rpy.z() * kRadToDeg};
      for (int i = 0; i < 8; ++i) rows[static_cast<size_t>(i)].error[a] = d[i];
    }
  }
  if (replay.options.estimate_odometer_delay) {  // the odometer's delay as a state
    Row r{"t_d_odo [s]", {}, {}, {NAN, NAN}};
    for (int a = 0; a < 2; ++a) {
      r.value[a] = runs[a].final().odometer_delay_s;
      r.sd[a] = runs[a].final().odometer_delay_sd_s;
    }
    rows.push_back(r);
  }
  // Table on the terminal.
  log << std::fixed << "giocal compare: " << job.data << "\n"
      << std::left << std::setw(17) << "" << std::right << std::setw(12) << "ekf" << std::setw(10)
      << "sigma" << std::setw(11) << "error"
      << " | " << std::setw(12) << "fgo" << std::setw(10) << "sigma" << std::setw(11) << "error"
      << "\n";
  for (const Row& r : rows) {
    log << std::left << std::setw(17) << r.name << std::right;
    for (int a = 0; a < 2; ++a) {
      log << std::setprecision(5) << std::setw(12) << r.value[a] << std::setw(10) << r.sd[a]
          << std::setw(11) << r.error[a] << (a == 0 ? " | " : "\n");
    }
  }
  std::ostringstream csv;
  csv << std::setprecision(12) << "quantity,ekf,ekf_sd,ekf_error,fgo,fgo_sd,fgo_error\n";
  for (const Row& r : rows) {
    csv << r.name;
    for (int a = 0; a < 2; ++a) csv << "," << r.value[a] << "," << r.sd[a] << "," << r.error[a];
    csv << "\n";
  }
  const char* stats[4] = {"fix rate [%]", "wall time [s]", "real-time factor", "GNSS epochs"};
  for (int i = 0; i < 4; ++i) {
    log << std::left << std::setw(17) << stats[i] << std::right;
    csv << stats[i];
    for (int a = 0; a < 2; ++a) {
      const CalibrationRun& r = runs[a];
      const double v[4] = {100.0 * r.fixRate(), r.wall_time_s,
                           r.wall_time_s > 0 ? r.data_duration_s / r.wall_time_s : 0.0,
                           static_cast<double>(r.gnss_epochs)};
      log << std::setprecision(i == 1 ? 3 : 1) << std::setw(12) << v[i] << std::setw(21) << ""
          << (a == 0 ? " | " : "\n");
      csv << "," << v[i] << ",,";
    }
    csv << "\n";
  }
  log << "(errors against truth_calib.yaml" << (truth ? "" : ": none in this dataset")
      << "; p_b_m.z held at the prior in both)\n";
  for (const CalibrationRun& r : runs) {
    for (const std::string& w : r.warnings) log << "  " << r.estimator << " warning: " << w << "\n";
  }
  outputs.open("compare.csv") << csv.str();
  outputs.commit();
  log << "outputs: " << out << "/{compare.csv, ekf/, fgo/}\n";
  log.unsetf(std::ios::fixed);
  bool suspect = false;
  for (const CalibrationRun& r : runs) {
    if (r.status != "ok") log << "  " << r.estimator << " status: " << r.status << "\n";
    suspect |= r.status.rfind("suspect", 0) == 0;
  }
  return suspect;
}

}  // namespace giocal
