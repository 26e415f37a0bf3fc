#include "ekf/ekf_core.h"

#include <algorithm>

#include "common/gnss/spp.h"
#include "common/io/text.h"
#include "ekf/imu_propagation.h"

namespace giocal {
namespace {

bool finiteState(const StateRegistry& s) {
  if (!s.covariance().allFinite()) return false;
  for (const StateKey& n : s.keys()) {
    if (!s.value(n).allFinite()) return false;
  }
  return true;
}

}  // namespace

EkfCore::EkfCore(const CalibrationOptions& options, const CalibrationInputs& sensors,
                 const BroadcastOrbits& orbits, const InitialState& init)
    : options_(options),
      sensors_(sensors),
      filter_(options, sensors.description, sensors.imu, init),
      gnss_(orbits, sensors.base_e, options),
      single_(orbits, options),
      next_output_(init.x.t) {}

void EkfCore::odometer(const OdomSample& sample, CalibrationRun& run) {
  const OdometerStep step = filter_.updateOdometer(sample);
  // The tallies exist from the first sample on (summary.json lists them at 0); afterwards a
  // sample touches one only when it changes (three look-ups by name per sample were 1 % of the
  // paper run's instructions).
  const long failures = filter_.takeNumericalFailures();
  if (failures || !odometer_tallied_) run.count(Counter::kNumericalFailures, failures);
  if (step.interval || !odometer_tallied_) run.count(Counter::kOdometerIntervals, step.interval);
  if (step.rejected || !odometer_tallied_) run.count(Counter::kOdometerRejected, step.rejected);
  odometer_tallied_ = true;
  if (!step.reopened) return;
  run.count(Counter::kCalibrationReopened);
  if (run.counter(Counter::kCalibrationReopened) > 1) return;
  run.warn(std::to_string(options_.max_odometer_rejections) +
           " odometer intervals in a row rejected by the innovation gate before t=" +
           timeText(sample.t) +
           ": the filter was more certain of its calibration than the odometer allows (a poor "
           "initial guess, wheel slip, wrong scale or time offset); the covariance of p_b_m and "
           "q_b_m was increased by the prior's (counter calibration_reopened)");
}

EpochOutcome EkfCore::position(double t, CalibrationRun& run) {
  EpochOutcome out;
  const PositionFix* fix = fixAt(sensors_.positions, t, kPositionTolerance);
  if (!fix) return out;
  out.used = filter_.updatePosition(*fix);
  run.count(Counter::kNumericalFailures, filter_.takeNumericalFailures());
  run.count(Counter::kGnssRowsRejected, out.used ? 0 : 3);
  out.diverged = !finiteState(filter_.state());
  if (out.diverged) return out;
  out.fixed = out.used && fix->quality == 1;
  out.recorded = true;
  out.estimate = filter_.calibration();
  return out;
}

EpochOutcome EkfCore::gnss(const ObsEpoch& rover, const ObsEpoch& base, CalibrationRun& run) {
  if (options_.loosely_coupled) return position(rover.t, run);
  const GnssEpochReport rep = options_.single_receiver ? single_.process(filter_, rover)
                                                       : gnss_.process(filter_, rover, base);
  for (const SatId& sat : single_.takeNewlyBroken())
    run.warn(brokenSatelliteWarning(sat, options_.single.tdcp.max_slips_in_a_row, rover.t));
  run.count(Counter::kTdcpRows, rep.tdcp_rows);
  run.count(Counter::kDopplerRows, rep.doppler_rows);
  run.count(Counter::kTdcpSlips, rep.tdcp_slips);
  run.count(Counter::kTdcpScreened, rep.tdcp_screened);
  run.count(Counter::kNumericalFailures, filter_.takeNumericalFailures());
  run.count(Counter::kDdRows, rep.dd_rows);
  run.count(Counter::kGnssRowsRejected, rep.rejected_rows);
  run.count(Counter::kCodeOutliers, rep.code_outliers);
  run.count(Counter::kAmbiguityResets, rep.ambiguity_resets);
  run.count(Counter::kFixesRejected, rep.fixes_rejected);
  run.count(Counter::kFixExclusions, rep.fix_exclusions);
  EpochOutcome out;
  out.diverged = rep.diverged || !finiteState(filter_.state());
  if (out.diverged) return out;
  out.used = rep.used;
  out.fixed = rep.fixed;
  out.recorded = true;
  out.estimate = filter_.calibration();
  return out;
}

void EkfCore::trajectoryUpTo(double t, const std::function<void(const TruthSample&)>& out) {
  while (next_output_ <= t) {
    out(filter_.trajectorySample(std::max(next_output_, filter_.time())));
    next_output_ += 1.0 / options_.output_rate_hz;
  }
}

double EkfCore::oldestSampleNeeded() const {
  // The IMU is integrated from the state's time; the motion detectors look half a window back.
  return filter_.time() - options_.models.motion.window_s;
}

}  // namespace giocal
