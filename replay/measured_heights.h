// The LC scheme's position solutions checked against the drive's IMU and odometer before
// calibrating (common/calibration/fix_heights.h): heights that stray well beyond their own sigmas
// get those sigmas scaled up, for both estimators alike (calibration.lc.learn_heights).
#pragma once

#include <string>
#include <vector>

#include "common/calibration/calibration_inputs.h"
#include "common/calibration/calibration_options.h"
#include "common/calibration/fix_heights.h"
#include "common/io/dataset_folder.h"

namespace giocal {

/// Heights straying less than this times their sigma are left as the receiver states them.
constexpr double kHeightScaleWorthApplying = 2.0;
/// Nor are heights straying less than this [m]: the profile from a MEMS IMU's grade is itself
/// good to about half a metre over kilometres (0.64 m robust spread against RTK heights true to
/// 2 cm, simulated field drive seed 3301, 1.9 km), so it cannot judge centimetre sigmas.
constexpr double kHeightProfileResolution = 2.0;

/// The check on the folder's logs (streamed; dataset.yaml's time offsets applied) and the
/// solutions (as read from the .pos file).
FixHeights measureFixHeights(const DatasetFolder& data, const std::vector<PositionFix>& positions);
/// The same on logs already loaded (their offsets applied).
FixHeights measureFixHeights(const CalibrationInputs& in);

/// Sets options.lc.height_sigma_scale to the check's scale when the options learn heights and the
/// scale is at least kHeightScaleWorthApplying; returns the scale set, 0 when none.
double applyFixHeights(const FixHeights& check, CalibrationOptions& options);

/// The warning a run gets when `scale` was applied.
std::string appliedHeightScaleWarning(const FixHeights& check);

}  // namespace giocal
