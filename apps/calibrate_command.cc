#include "apps/calibrate_command.h"

#include <filesystem>
#include <iomanip>
#include <ostream>
#include <stdexcept>

#include "apps/live_run_writer.h"
#include "apps/prior_file.h"
#include "apps/run_validation.h"
#include "apps/state_file.h"
#include "common/calibration/calibration_options.h"
#include "common/calibration/fix_audit.h"
#include "common/calibration/warm_start.h"
#include "common/io/text.h"
#include "common/math/rotation.h"
#include "options/giocal_config.h"
#include "replay/estimator_factory.h"
#include "replay/replay.h"
#include "replay/run_preparation.h"

namespace giocal {

void printCalibrationSummary(const CalibrationRun& run, const OdometerCalibration* truth,
                             std::ostream& out) {
  if (!run.latest) {
    out << run.estimator << ": no calibration estimate\n";
    return;
  }
  const CalibrationEstimate& e = *run.latest;
  const Eigen::Vector3d rpy = rpyFromRotation(e.calib.q_b_m.toRotationMatrix()) * kRadToDeg;
  const Eigen::Matrix<double, 8, 1> sd = e.sigma();
  CalibrationError err;
  if (truth) err = calibrationError(e, *truth);
  out << std::fixed;
  const auto row = [&](const char* name, double v, double s, double er, int prec) {
    out << "  " << std::left << std::setw(10) << name << std::right << std::setprecision(prec)
        << std::setw(12) << v << " +- " << std::setw(prec + 4) << s;
    if (truth) out << "   error " << std::setw(prec + 5) << er;
    out << "\n";
  };
  out << run.estimator << " calibration at t=" << std::setprecision(2) << e.t << ":\n";
  row("s_v", e.calib.s_v, sd[0], err.s_v, 5);
  row("s_w", e.calib.s_w, sd[1], err.s_w, 5);
  const char* pn[3] = {"p_b_m.x m", "p_b_m.y m", "p_b_m.z m"};
  for (int k = 0; k < 3; ++k) row(pn[k], e.calib.p_b_m[k], sd[2 + k], err.p_b_m[k], 4);
  const char* rn[3] = {"roll deg", "pitch deg", "yaw deg"};
  for (int k = 0; k < 3; ++k) row(rn[k], rpy[k], sd[5 + k], err.rpy[k] * kRadToDeg, 3);
  if (std::isfinite(e.odometer_delay_s)) {
    out << "  " << std::left << std::setw(10) << "t_d_odo s" << std::right << std::setprecision(4)
        << std::setw(12) << e.odometer_delay_s << " +- " << std::setw(8) << e.odometer_delay_sd_s
        << "   (the odometer's delay against the IMU)\n";
  }
  if (e.gyro_tilt.allFinite()) {
    for (int k = 0; k < 2; ++k) {
      out << "  " << std::left << std::setw(10) << (k == 0 ? "tilt.x deg" : "tilt.y deg")
          << std::right << std::setprecision(4) << std::setw(12) << e.gyro_tilt[k] * kRadToDeg
          << " +- " << std::setw(8) << e.gyro_tilt_sd[k] * kRadToDeg
          << (k == 0 ? "   (the gyro triad's tilt against the accelerometer's)\n" : "\n");
    }
  }
  if (truth) out << "  NEES (7 observable states) " << std::setprecision(2) << err.nees7 << "\n";
  out << "  lever arm along the vertical: " << run.p_b_m_z << "\n";
  out << std::setprecision(1) << "  GNSS epochs " << run.gnss_epochs << ", fix rate "
      << 100.0 * run.fixRate() << " %; " << std::setprecision(3) << run.wall_time_s << " s for "
      << std::setprecision(1) << run.data_duration_s << " s of data (" << std::setprecision(0)
      << (run.wall_time_s > 0 ? run.data_duration_s / run.wall_time_s : 0.0)
      << "x real time), files read in " << std::setprecision(3) << run.load_time_s << " s\n";
  for (const std::string& w : run.warnings) out << "  warning: " << w << "\n";
  out.unsetf(std::ios::fixed);
}

namespace {

// The run checks its own calibration on its drive (validate's windows) before its summary is
// written: the verdict goes into summary.json, and a calibration that dead-reckons worse than
// the guess makes the run suspect.
void validateOwnRun(const DatasetFolder& data, const GiocalConfig& config, const ReplayJob& replay,
                    OutputSet& outputs, const CalibrateJob& job, RunWriter& writer,
                    CalibrationRun& run, std::ostream& log) {
  writer.closeFiles();  // calibration.csv, read by the windows
  const RunValidation v =
      validateAtEnd(data, config, replay.options, job.positions, outputs.staging(), job.stop);
  run.validation = v;
  if (v.verdict.empty()) {
    log << "  validation: not done (" << v.why_not << ")\n";
    return;
  }
  log << "  validation: " << v.verdict << " (dead reckoning through " << v.windows
      << " GNSS outage windows: " << fixedText(v.calibrated_m, 2) << " m calibrated against "
      << fixedText(v.guess_m, 2) << " m with the guess, better in " << v.better_windows << ")\n";
  if (v.verdict == "worse" && run.status == "ok") {
    run.status =
        "suspect: the calibration dead-reckons worse than the initial guess in the "
        "validation windows (ratio " +
        fixedText(v.ratio, 2) + ")";
  }
}

}  // namespace

CalibrationRun runCalibrate(const CalibrateJob& job, std::ostream& log) {
  ReplayJob replay;
  replay.estimator = job.estimator;
  const GiocalConfig config = readGiocalConfig(job.config);
  replay.options = config.calibration;
  replay.fgo_options = config.fgo;
  replay.positions = job.positions;
  replay.options_in_effect = config.in_effect;
  replay.options.loosely_coupled = !job.positions.empty();
  coreFactory(job.estimator, replay.options);  // an unknown estimator fails before any output
  if (!job.overwrite) {
    for (const std::string& f : calibrationOutputFiles()) {
      if (std::filesystem::exists(job.out + "/" + f)) {
        throw std::runtime_error(job.out + "/" + f +
                                 " exists; give --overwrite to replace the outputs");
      }
    }
  }
  replay.stop = job.stop;
  DatasetFolder data = openDatasetFolder(job.data);  // once for the whole run
  chooseSingleReceiver(data.description, job.single, replay, log);
  // Warm start: the earlier drive's calibration, its covariance grown for the days between.
  std::string warm;
  std::optional<PriorFile> prior;
  if (!job.prior.empty()) {
    try {
      prior = readPriorFile(job.prior);
    } catch (const DamagedPrior& e) {
      warm = std::string(e.what()) + ": the run starts cold, from dataset.yaml's initial guess";
      log << "  " << warm << "\n";
    }
  }
  if (prior) {
    const PriorFile& p = *prior;
    const std::string differs = robotMismatch(p.robot, robotFingerprint(data.description));
    if (!differs.empty()) {
      throw std::runtime_error("--prior " + job.prior + " is another robot's: dataset.yaml's " +
                               differs);
    }
    const double dt = data.imu_span.first - p.t_final;
    data.description.initial_calibration =
        carriedPrior(p.calibration, dt, replay.options.warm_start);
    warm = "started from " + job.prior + " (" + fixedText(std::max(0.0, dt) / 86400.0, 2) +
           " days earlier; covariance grown by calibration.warm_start's drift per sqrt(day))";
    log << "  " << warm << "\n";
  }
  const RunPreparation prepared = prepareRun(data, replay, log);
  OutputSet outputs(job.out);
  const auto span = data.imu_span;
  ProgressLine progress("calibrate " + job.estimator, span.first, span.second, job.quiet);
  LiveRunWriter writer(outputs, "", job.estimator, log, &progress);
  // Where the dataset has a truth, each fixed epoch is checked against it as the run goes.
  const std::unique_ptr<FixAudit> audit = fixAuditOf(data, &writer);
  RunSink* sink = audit ? static_cast<RunSink*>(audit.get()) : &writer;
  // A robot's state across power cycles: written every state_every_s of data, and at the end.
  const std::map<std::string, double> robot = robotFingerprint(data.description);
  std::optional<StateFileSink> state;
  if (!job.state_out.empty()) sink = &state.emplace(sink, job.state_out, job.state_every_s, robot);
  CalibrationRun run = replayCheckingPositions(data, replay, sink);
  if (state && run.latest) writeStateFile(job.state_out, *run.latest, robot);
  if (audit) audit->addTo(run);
  progress.clear();
  notePreparation(prepared, data, run);
  if (!warm.empty()) run.warn(warm);
  const std::optional<TruthCalibration>& truth = data.truth;
  if (job.validate) validateOwnRun(data, config, replay, outputs, job, writer, run, log);
  writer.finish(run, truth ? &truth->calib : nullptr);
  outputs.commit();
  printCalibrationSummary(run, truth ? &truth->calib : nullptr, log);
  log << "  outputs: " << job.out << "/{calibration.csv, trajectory.csv, summary.json}\n";
  if (run.status != "ok") log << "  status: " << run.status << "\n";  // last: what to trust
  return run;
}

}  // namespace giocal
