// Replays recorded data through the online Calibrator, in time order: a dataset folder read
// incrementally (calibrate, compare), or data already in memory (tests, Monte Carlo).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>

#include "common/calibration/calibration_inputs.h"
#include "common/io/dataset_folder.h"
#include "common/io/stop_request.h"
#include "common/online/calibrator.h"
#include "options/fgo_options.h"

namespace giocal {

struct ReplayJob {
  ReplayJob() = default;
  ReplayJob(std::string estimator_name, CalibrationOptions calibration, FgoOptions fgo)
      : estimator(std::move(estimator_name)),
        options(std::move(calibration)),
        fgo_options(std::move(fgo)) {}

  std::string estimator = "ekf";
  CalibrationOptions options;
  FgoOptions fgo_options;
  const StopRequest* stop = nullptr;  // when requested, the replay throws Interrupted
  std::string positions;  // the LC scheme's .pos file (options.loosely_coupled), else empty
  std::map<std::string, std::string> options_in_effect;  // recorded in the run (summary.json)
};

/// Reads the folder's files sample by sample while calibrating (memory does not grow with the
/// log). run.load_time_s is the time spent reading. Throws DataError for bad files (naming the
/// file and line) and std::runtime_error when no initial state is ever found.
CalibrationRun replayFolder(const DatasetFolder& data, const ReplayJob& job, RunSink* sink);
/// The same, the folder opened here.
CalibrationRun replayFolder(const std::string& folder, const ReplayJob& job, RunSink* sink);

/// The same from loaded inputs.
CalibrationRun replayInputs(const CalibrationInputs& in, const ReplayJob& job, RunSink* sink);

}  // namespace giocal
