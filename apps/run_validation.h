// Validation of a calibration against the dataset's own GNSS, for `validate` and for
// `calibrate`'s check at its end: the reference (the dataset's RTK fixes, or the LC solutions)
// and the windows dead-reckoned with the calibration and with the guess (evaluation/validation.h).
#pragma once

#include <string>
#include <vector>

#include "common/calibration/calibration_inputs.h"
#include "common/calibration/calibration_run.h"
#include "common/gnss/pos_reader.h"
#include "common/io/dataset_folder.h"
#include "common/io/stop_request.h"
#include "options/giocal_config.h"

namespace giocal {

struct ValidationReference {
  std::vector<PositionFix> fixes;
  std::string name;  // for messages and summary.json
};

/// The dataset's fixed RTK solutions (written to `pos`), with `positions` the LC solutions
/// already in `in`, or with `single` the rover's own track already in `in`
/// (addSingleReceiverTrack; its offset is metres: the windows compare displacements from their
/// start). Throws std::runtime_error when it has fewer than two rows, or when the dataset has no
/// base and neither is asked for.
ValidationReference validationReference(const CalibrationInputs& in, const GiocalConfig& config,
                                        const std::string& positions, const std::string& pos,
                                        const StopRequest* stop, bool single = false);

/// calibrate's check of its calibration at its end: `run_dir` holds the run's calibration.csv;
/// `options` are those the run used. A drive too short or no GNSS reference gives a result that
/// says why not, not an error.
RunValidation validateAtEnd(const DatasetFolder& data, const GiocalConfig& config,
                            const CalibrationOptions& options, const std::string& positions,
                            const std::string& run_dir, const StopRequest* stop);

}  // namespace giocal
