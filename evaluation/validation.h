// Validation of a calibration on the user's own drive, without a truth: GNSS outages cut into
// the drive at several windows, each dead-reckoned with the calibration as it stood when the
// window began (it had not seen that window's GNSS) and with the initial guess, both against the
// GNSS solution inside the window.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "common/calibration/calibration_inputs.h"
#include "common/calibration/calibration_options.h"
#include "common/calibration/calibration_run.h"
#include "common/calibration/reference_trajectory.h"

namespace giocal {

struct ValidationJob {
  std::string run;         // a calibrate output folder (its calibration.csv and summary.json)
  double outage_s = 60.0;  // each window's length
  int windows = 5;         // spread over the drive (fewer when the drive is short)
  CalibrationOptions options;
  bool reference_has_attitude = false;   // a GNSS solution has none
  bool relative_to_start = false;        // one receiver's own track (DeadReckoningJob)
  std::function<void(double)> progress;  // the share of the windows done (may throw to stop)
};

struct Validation {
  std::vector<ValidationWindow> windows;
  double calibrated_m = 0.0, guess_m = 0.0;  // means over the windows
  double ratio = 0.0;                        // calibrated / guess
  int better_windows = 0;                    // windows where the calibration did better
  // "better", "no better" or "worse": the mean ratio beyond 10 % and a majority of the windows
  // the same way; confidence: 1 - the sign test's one-sided p-value for that majority (0 for
  // "no better").
  std::string verdict;
  double confidence = 0.0;
};

/// The windows' starts [GPS s]: spread evenly from the earliest the run allows (its first
/// calibration.csv row, plus a margin) to the latest (the reference's end minus an outage), each
/// moved past a gap in the reference it would start in. Throws std::runtime_error saying how much
/// drive it needs when not even one window fits, or that the reference has no solution to start
/// one at.
std::vector<double> validationWindowStarts(const CalibrationInputs& in,
                                           const ReferenceTrajectory& reference,
                                           double first_calibration_s, const ValidationJob& job);

/// Throws std::runtime_error for a run whose calibration.csv is missing or a drive too short.
/// `in` is taken by value (move it in): each window's runs change its odometer stamps.
Validation validateCalibration(CalibrationInputs in, const ReferenceTrajectory& reference,
                               const ValidationJob& job);

}  // namespace giocal
