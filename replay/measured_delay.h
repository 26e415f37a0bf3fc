// The odometer's delay against the IMU measured on a dataset's logs before calibrating (the yaw
// rate both see, read as a stream: constant memory), and put into the dataset's time offsets
// when it is beyond doubt (calibration.apply_odometer_delay_*).
#pragma once

#include "common/calibration/calibration_options.h"
#include "common/calibration/odometer_delay.h"
#include "common/io/dataset_folder.h"

namespace giocal {

/// The delay of odom.csv against imu.csv, after dataset.yaml's time_offsets; not valid for a
/// speed-only odometer (its yaw rate is the gyro's) or a drive without turns.
OdometerDelay measureOdometerDelay(const DatasetFolder& data);

/// Measures it and, when worthApplying() with the options' bounds (and the delay is not to be
/// estimated as a state), takes it out: data.description.time_offsets.odometer -= delay. Returns
/// the delay taken out, 0 when none.
double applyMeasuredOdometerDelay(DatasetFolder& data, const CalibrationOptions& options);

/// The warning a run gets when `applied` was taken out before it.
std::string appliedDelayWarning(double applied, const DatasetFolder& data);

}  // namespace giocal
