// runFgoCalibration(): the sliding-window factor-graph calibrator over a whole dataset: one state
// per GNSS epoch joined by IMU and odometer preintegration, DD code/phase and Doppler factors,
// motion constraints, ambiguity fixes; the oldest epoch is marginalized into a prior.
#pragma once

#include "common/calibration/calibration_inputs.h"
#include "common/calibration/calibration_options.h"
#include "common/calibration/calibration_run.h"
#include "fgo/fgo_options.h"

namespace giocal {

/// Throws std::runtime_error when the data never allow an initial state (the message says why).
CalibrationRun runFgoCalibration(const CalibrationInputs& inputs, const CalibrationOptions& options,
                                 const FgoOptions& fgo_options = {});

}  // namespace giocal
