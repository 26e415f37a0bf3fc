// EstimatorCore: what one estimator (EKF or factor graph) does once initialized, fed by the online
// Calibrator (common/online/calibrator.h) with time-ordered events. The Calibrator owns what both
// share: sensor buffers, reordering, initialization, base matching, counters, outputs.
#pragma once

#include <functional>
#include <string>

#include "common/calibration/calibration_run.h"
#include "common/imu/nav_state.h"
#include "common/io/sensor_logs.h"
#include "common/odometer/odom_sample.h"

namespace giocal {

struct ObsEpoch;

/// What one GNSS epoch did.
struct EpochOutcome {
  bool used = false;      // counts as a GNSS epoch of the run
  bool fixed = false;     // validated ambiguity fixes hold in it
  bool diverged = false;  // the estimator lost track (the Calibrator re-initializes)
  bool recorded = false;  // `estimate` is the calibration after this epoch
  CalibrationEstimate estimate;
};

class EstimatorCore {
 public:
  virtual ~EstimatorCore() = default;

  /// Whether each odometer sample is an event (EKF); else the core reads the buffered samples
  /// between GNSS epochs itself (factor graph).
  virtual bool takesOdometerEvents() const = 0;
  /// Time of the state: events before it are skipped.
  virtual double time() const = 0;
  /// Whether a rover epoch at t is still new to the core.
  virtual bool acceptsEpoch(double t) const = 0;

  virtual void odometer(const OdomSample& /*sample*/, CalibrationRun& /*run*/) {}
  virtual EpochOutcome gnss(const ObsEpoch& rover, const ObsEpoch& base, CalibrationRun& run) = 0;

  virtual CalibrationEstimate calibration() const = 0;
  virtual NavState nav() const = 0;
  /// Hands out the trajectory samples (calibration.output_rate_hz) up to data time t.
  virtual void trajectoryUpTo(double t, const std::function<void(const TruthSample&)>& out) = 0;
  /// The oldest IMU or odometer time the core may still read: earlier samples may be dropped.
  virtual double oldestSampleNeeded() const = 0;
};

}  // namespace giocal
