// `giocal calibrate --data <dir> [--estimator ekf|fgo] [--config <yaml>] --out <dir>`.
#pragma once

#include <iosfwd>
#include <string>

#include "common/calibration/calibration_run.h"
#include "common/io/stop_request.h"

namespace giocal {

struct CalibrateJob {
  std::string data, estimator = "ekf", config, out;
  bool overwrite = false;
  bool quiet = false;     // no progress line
  std::string positions;  // --gnss lc --pos <file.pos>: the LC scheme
  bool single = false;    // --gnss single (also taken when dataset.yaml names no base)
  std::string prior;      // --prior <summary.json or state file>: start from an earlier calibration
  std::string state_out;  // --state-out <file>: the calibration kept across power cycles
  double state_every_s = 60.0;  // --state-every: seconds of data between its writes
  bool validate = true;  // check the calibration on its drive at the end (not with --no-validate)
  const StopRequest* stop = nullptr;  // Ctrl-C: the run stops and writes nothing
};

/// Runs one estimator on a dataset folder, writes the outputs, prints a summary. Refuses to
/// replace existing outputs unless job.overwrite.
CalibrationRun runCalibrate(const CalibrateJob& job, std::ostream& log);

/// Final calibration with 1-sigma (and errors when the truth is known), fix rate and speed.
void printCalibrationSummary(const CalibrationRun& run, const OdometerCalibration* truth,
                             std::ostream& out);

}  // namespace giocal
