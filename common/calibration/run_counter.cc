#include "common/calibration/run_counter.h"

namespace giocal {

const char* counterName(Counter c) {
  switch (c) {
    case Counter::kOdometerIntervals:
      return "odometer_intervals";
    case Counter::kOdometerRejected:
      return "odometer_rejected";
    case Counter::kCalibrationReopened:
      return "calibration_reopened";
    case Counter::kDdRows:
      return "dd_rows";
    case Counter::kGnssRowsRejected:
      return "gnss_rows_rejected";
    case Counter::kGnssEpochsUnused:
      return "gnss_epochs_unused";
    case Counter::kCodeOutliers:
      return "code_outliers";
    case Counter::kDopplerRows:
      return "doppler_rows";
    case Counter::kTdcpRows:
      return "tdcp_rows";
    case Counter::kTdcpSlips:
      return "tdcp_slips";
    case Counter::kTdcpScreened:
      return "tdcp_screened";
    case Counter::kAmbiguityResets:
      return "ambiguity_resets";
    case Counter::kFixesRejected:
      return "fixes_rejected";
    case Counter::kFixExclusions:
      return "fix_exclusions";
    case Counter::kGnssWithoutBase:
      return "gnss_without_base";
    case Counter::kReinitializations:
      return "reinitializations";
    case Counter::kImuGaps:
      return "imu_gaps";
    case Counter::kImuRestarts:
      return "imu_restarts";
    case Counter::kLateSamples:
      return "late_samples_dropped";
    case Counter::kFutureSamples:
      return "future_samples_dropped";
    case Counter::kDuplicateSamples:
      return "duplicate_samples_dropped";
    case Counter::kNonFiniteSamples:
      return "non_finite_samples_dropped";
    case Counter::kDroppedWithoutImu:
      return "dropped_while_imu_silent";
    case Counter::kOdometerGaps:
      return "odometer_gaps";
    case Counter::kGnssGaps:
      return "gnss_gaps";
    case Counter::kCalibrationJumps:
      return "calibration_jumps";
    case Counter::kOdometerSlips:
      return "odometer_slips";
    case Counter::kNumericalFailures:
      return "numerical_failures";
    case Counter::kSize:
      break;
  }
  return "unknown";
}

}  // namespace giocal
