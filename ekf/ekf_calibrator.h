// runEkfCalibration(): the EKF calibrator over a whole dataset: initialization, then odometer and
// GNSS epochs in time order with the IMU in between, bad-data handling (gaps, divergence and
// re-initialization), and the calibration history and trajectory the outputs are written from.
#pragma once

#include "common/calibration/calibration_inputs.h"
#include "common/calibration/calibration_options.h"
#include "common/calibration/calibration_run.h"

namespace giocal {

/// Throws std::runtime_error when the data never allow an initial state (the message says why).
CalibrationRun runEkfCalibration(const CalibrationInputs& inputs,
                                 const CalibrationOptions& options);

}  // namespace giocal
