// EkfCore: the error-state EKF as the online Calibrator's estimator: odometer samples and GNSS
// epochs update CalibrationFilter (ekf/calibration_filter.h) through GnssUpdate.
#pragma once

#include "common/calibration/calibration_inputs.h"
#include "common/online/estimator_core.h"
#include "ekf/calibration_filter.h"
#include "ekf/gnss_update.h"
#include "ekf/single_receiver_update.h"

namespace giocal {

class EkfCore : public EstimatorCore {
 public:
  /// `sensors` (the Calibrator's buffers) and `orbits` must outlive the core.
  EkfCore(const CalibrationOptions& options, const CalibrationInputs& sensors,
          const BroadcastOrbits& orbits, const InitialState& init);

  bool takesOdometerEvents() const override { return true; }
  double time() const override { return filter_.time(); }
  bool acceptsEpoch(double t) const override { return t >= filter_.time(); }
  void odometer(const OdomSample& sample, CalibrationRun& run) override;
  EpochOutcome gnss(const ObsEpoch& rover, const ObsEpoch& base, CalibrationRun& run) override;
  CalibrationEstimate calibration() const override { return filter_.calibration(); }
  NavState nav() const override { return filter_.nav(); }
  void trajectoryUpTo(double t, const std::function<void(const TruthSample&)>& out) override;
  double oldestSampleNeeded() const override;

 private:
  /// The LC scheme's epoch: the antenna position solution at the rover epoch's time, if any.
  EpochOutcome position(double t, CalibrationRun& run);

  CalibrationOptions options_;
  const CalibrationInputs& sensors_;
  CalibrationFilter filter_;
  GnssUpdate gnss_;
  SingleReceiverUpdate single_;  // options.single_receiver: rover epochs without a base
  double next_output_;
  bool odometer_tallied_ = false;  // the odometer's counters exist in the run
};

}  // namespace giocal
