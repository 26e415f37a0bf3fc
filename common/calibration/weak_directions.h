// Weak directions: calibration states whose final sigma is still close to the prior's, i.e. the
// data hold little information about them; said in the run's warnings.
#pragma once

#include <string>
#include <vector>

#include "common/calibration/calibration_options.h"
#include "common/calibration/calibration_run.h"
#include "common/io/dataset_description.h"

namespace giocal {

/// One message per observable state (s_v, s_w, p_b_m x and y, roll, pitch, yaw) whose 1-sigma in
/// `final` is above `fraction` of the prior's: the data then add less than 1/fraction^2 - 1 times
/// the prior's information (10 times at 0.3), the estimate stays near the guess, and along such a
/// direction the reported sigma has been measured too small (docs/results.md). p_b_m's vertical
/// component (verticalLeverState) is left out: it is unobservable under planar motion and
/// summary.json says how it was treated; so are
/// the `held` states (calibration.csv order), which the run does not calibrate (s_w with a
/// speed-only odometer).
std::vector<std::string> weakDirections(const CalibrationEstimate& final,
                                        const CalibrationPrior& prior,
                                        const std::vector<int>& held = {}, double fraction = 0.3);

/// The p_b_m component (calibration.csv order: calib_index::kP + 0, 1 or 2) along which the
/// guess's vehicle vertical (R_b_m e_z) lies closest: the lever arm planar motion leaves
/// unobservable. p_b_m.z for an IMU mounted z up; p_b_m.y for one on its side (gravity on y).
int verticalLeverState(const CalibrationPrior& prior);

/// The states (calibration.csv order) a run does not calibrate and so never calls weak: s_w of
/// a speed-only odometer, p_b_m's vertical component (verticalLeverState) when held.
std::vector<int> heldStates(const CalibrationOptions& options, const DatasetDescription& d);

/// The indices (calibration.csv order, calibrationStateName()) of the states weakDirections()
/// names.
std::vector<int> weakStates(const CalibrationEstimate& final, const CalibrationPrior& prior,
                            const std::vector<int>& held = {}, double fraction = 0.3);

/// "s_v", "s_w", "p_b_m.x", ..., "yaw of q_b_m" for index 0..7 of calibration.csv's order, and
/// the unit of its sigma (" m", " deg" or "").
const char* calibrationStateName(int k);
const char* calibrationStateUnit(int k);

/// The motion that informs state k (the paper's observability analysis, in words); for p_b_m,
/// its horizontal components (the vertical one, which planar motion leaves unobservable, is
/// said apart).
const char* motionThatInforms(int k);

}  // namespace giocal
