// RunPreparation: what is measured on a dataset's logs before calibrating and acted on, for
// calibrate and compare alike: the odometer's delay (measured_delay.h) and, in the LC scheme, the
// position solutions' heights (measured_heights.h); after it, how well those solutions support
// the run's sigmas (position_residuals.h).
#pragma once

#include <iosfwd>

#include "common/calibration/calibration_run.h"
#include "common/io/dataset_folder.h"
#include "replay/replay.h"

namespace giocal {

struct RunPreparation {
  double delay_applied_s = 0.0;       // taken out of the odometer's stamps (0: none)
  std::optional<FixHeights> heights;  // the LC scheme's check
  double height_scale_applied = 0.0;  // put on the solutions' height sigmas (0: none)
};

/// Whether a run takes the single-receiver scheme: asked (--gnss single), or a rover alone in
/// the dataset and no position solutions given.
bool usesSingleReceiver(const DatasetDescription& d, bool asked, const std::string& positions);

/// Sets job.options.single_receiver as usesSingleReceiver says; when the dataset decided it, one
/// line to `log` says so.
void chooseSingleReceiver(const DatasetDescription& d, bool asked, ReplayJob& job,
                          std::ostream& log);

/// Measures and acts: data's time offsets and job.options change where the measures say so;
/// one line to `log` for each change.
RunPreparation prepareRun(DatasetFolder& data, ReplayJob& job, std::ostream& log);

/// Puts what the preparation did into the run's summary and warnings.
void notePreparation(const RunPreparation& p, const DatasetFolder& data, CalibrationRun& run);

/// replayFolder, with the LC scheme's solutions checked against the trajectory as it streams
/// past (PositionResidualSink): run.lc_residuals, and a warning when they support much less than
/// the run's sigmas assume.
CalibrationRun replayCheckingPositions(DatasetFolder& data, const ReplayJob& job, RunSink* sink);

}  // namespace giocal
