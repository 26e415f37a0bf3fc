// Dead reckoning with a given calibration: IMU + odometer navigation (odometer preintegration,
// non-holonomic and zero-velocity constraints: the EKF's models with every calibration state
// held) through a GNSS outage, and its error against a reference trajectory (the paper's test of
// what a calibration is worth).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "common/calibration/calibration_inputs.h"
#include "common/calibration/calibration_options.h"
#include "common/calibration/reference_trajectory.h"

namespace giocal {

struct DeadReckoningJob {
  double start_s = 100.0;        // outage start, seconds after the first rover epoch
  double duration_s = 1000.0;    // outage length (cut at the end of the data or the reference)
  CalibrationPrior calibration;  // the calibration used, held; its covariance enters as consider
  CalibrationOptions options;    // options.loosely_coupled: aided by in.positions before the start
  // false (a reference of GNSS positions): the GNSS-aided state at the start is kept, not moved
  // onto the reference.
  bool reference_has_attitude = true;
  // true (one receiver's own track, whose offset is a single point position's metres): errors
  // are displacement errors from the outage start (the start's error taken out of every later
  // one), compared up to the reference's first gap.
  bool relative_to_start = false;
  std::function<void(double)> progress;  // called with the data time reached (may throw to stop)
};

struct DeadReckoningError {
  double t = 0.0;         // data time
  double elapsed = 0.0;   // since the outage start [s]
  double distance = 0.0;  // horizontal distance travelled by the reference since the start [m]
  Eigen::Vector3d enu = Eigen::Vector3d::Zero();  // dead-reckoned minus reference, at the reference
  double horizontal() const { return enu.head<2>().norm(); }
};

struct DeadReckoning {
  double t_start = 0.0, t_end = 0.0;
  double aided_s = 0.0;  // GNSS-aided time before the start (biases and velocity settle there)
  std::vector<TruthSample> trajectory;  // dead-reckoned, at options.output_rate_hz
  std::vector<DeadReckoningError> errors;
  double horizontal_max_m = 0.0, horizontal_rmse_m = 0.0, distance_m = 0.0;
  double final_error_m = 0.0, final_error_percent_of_distance = 0.0;
};

/// Runs the filter GNSS-aided (calibration held) from the first possible initial state to the
/// start, moves its pose and velocity to the reference's there (IMU biases stay as estimated;
/// not with a reference without attitude),
/// then navigates on IMU and odometer alone. Throws std::runtime_error when the start cannot be
/// reached (no initial state before it, no reference there).
DeadReckoning deadReckon(const CalibrationInputs& in, const ReferenceTrajectory& reference,
                         const DeadReckoningJob& job);

}  // namespace giocal
