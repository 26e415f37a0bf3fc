#include "replay/run_preparation.h"

#include <ostream>

#include "common/gnss/pos_reader.h"
#include "common/io/text.h"
#include "common/online/position_residual_sink.h"
#include "replay/measured_delay.h"
#include "replay/measured_heights.h"

namespace giocal {

RunPreparation prepareRun(DatasetFolder& data, ReplayJob& job, std::ostream& log) {
  RunPreparation p;
  // An odometer measured late beyond doubt is put back on time before calibrating.
  p.delay_applied_s = applyMeasuredOdometerDelay(data, job.options);
  if (p.delay_applied_s != 0.0) {
    log << "  the odometer's stamps are " << fixedText(p.delay_applied_s * 1e3, 0)
        << " ms late against the IMU's (measured on the logs): taken out for this run\n";
  }
  // Solutions whose heights stray far beyond their sigmas are weighed by what they show.
  if (!job.positions.empty() && job.options.lc.use_height && job.options.lc.learn_heights) {
    p.heights = measureFixHeights(data, readPosFile(job.positions));
    p.height_scale_applied = applyFixHeights(*p.heights, job.options);
    if (p.height_scale_applied != 0.0) {
      log << "  the position solutions' heights stray " << fixedText(p.heights->spread_m, 1)
          << " m from the drive's own (their sigma " << fixedText(p.heights->reported_sigma_m, 1)
          << " m): their height sigmas x" << fixedText(p.height_scale_applied, 1)
          << " for this run\n";
    }
  }
  return p;
}

void notePreparation(const RunPreparation& p, const DatasetFolder& data, CalibrationRun& run) {
  if (p.delay_applied_s != 0.0) {
    run.odometer_delay_applied_s = p.delay_applied_s;
    run.warn(appliedDelayWarning(p.delay_applied_s, data));
  }
  run.lc_heights = p.heights;
  run.lc_height_scale_applied = p.height_scale_applied;
  if (p.height_scale_applied != 0.0) run.warn(appliedHeightScaleWarning(*p.heights));
}

CalibrationRun replayCheckingPositions(DatasetFolder& data, const ReplayJob& job, RunSink* sink) {
  if (job.positions.empty()) return replayFolder(data, job, sink);
  PositionResidualSink residuals(sink, readPosFile(job.positions), data.description.p_b_g);
  CalibrationRun run = replayFolder(data, job, &residuals);
  run.lc_residuals = residuals.result();
  const std::string why = understatedSigmaWarning(*run.lc_residuals);
  if (!why.empty()) run.warn(why);
  return run;
}

bool usesSingleReceiver(const DatasetDescription& d, bool asked, const std::string& positions) {
  return asked || (positions.empty() && d.roverAlone());
}

void chooseSingleReceiver(const DatasetDescription& d, bool asked, ReplayJob& job,
                          std::ostream& log) {
  job.options.single_receiver = usesSingleReceiver(d, asked, job.positions);
  if (!asked && job.options.single_receiver) {
    log << "  dataset.yaml names no base observations: the single-receiver scheme (--gnss "
           "single)\n";
  }
}

}  // namespace giocal
