// The calibration a user names for dead reckoning: a calibrate run's summary.json, its
// calibration.csv at a time, the dataset's truth or its initial guess.
#pragma once

#include <string>

#include "common/calibration/calibration_inputs.h"

namespace giocal {

struct CalibrationSource {
  CalibrationPrior calibration;  // mean and covariance
  std::string label;             // what it is, for outputs
  // The odometer's delay a run estimated (summary.json's final.t_d_odo), else 0 [s].
  double odometer_delay_s = 0.0;
  // The gyro's tilt against the accelerometer (final.gyro_tilt_deg, or the truth's) [rad]; NaN
  // when the source has none.
  Eigen::Vector2d gyro_tilt = Eigen::Vector2d::Constant(NAN);
  double gyro_tilt_sd = 0.0;  // its sigma, the larger axis's [rad]
};

/// `source`: "<dir>/summary.json" (final values and covariance; the run's output set is checked),
/// "<file>.csv@<seconds>" (the last row at or before that many seconds after the first rover
/// epoch of the run that wrote it, from the summary.json beside it, else of `in`; covariance from
/// its sigma columns), "truth" (truth_calib.yaml, no uncertainty), "guess" (dataset.yaml's
/// initial calibration and sigmas), or "truth:<dataset>" / "guess:<dataset>" of another dataset.
/// Throws DataError or std::runtime_error saying what is wrong with it.
CalibrationSource readCalibrationSource(const std::string& source, const CalibrationInputs& in);

struct DeadReckoningJob;
/// Dead reckoning with `source`: its calibration held, its odometer delay taken out of `odom`'s
/// stamps (they are put back on time), its gyro tilt integrated with the IMU.
void applyCalibrationSource(const CalibrationSource& source, DeadReckoningJob& job,
                            std::vector<OdomSample>& odom);

}  // namespace giocal
