// Counter: the named tallies every calibration run keeps (the keys of summary.json's "counters").
#pragma once

#include <functional>
#include <map>
#include <string>

namespace giocal {

enum class Counter {
  kOdometerIntervals,    // odometer intervals that updated the filter
  kOdometerRejected,     // of those, gated out
  kCalibrationReopened,  // extrinsic covariance re-opened after rejections in a row
  kDdRows,               // DD code and phase rows used
  kGnssRowsRejected,     // DD rows rejected by a gate or after a solve
  kGnssEpochsUnused,     // GNSS epochs (LC: position fixes) that updated nothing
  kCodeOutliers,         // pseudo-ranges flagged by the Doppler-predicted change
  kDopplerRows,          // Doppler rows used
  kTdcpRows,             // single receiver: time-differenced phase rows used
  kTdcpSlips,            // single receiver: phases left out of a pair (slip or half cycle)
  kTdcpScreened,         // single receiver: phases off the predicted displacement, left out
  kAmbiguityResets,      // ambiguities restarted (slip or rejected phase row)
  kFixesRejected,        // LAMBDA fixes that failed validation
  kFixExclusions,        // of those, tried again without the satellite of the worst row
  kGnssWithoutBase,      // rover epochs with no base epoch near enough
  kReinitializations,    // restarts after divergence
  kImuGaps,              // IMU intervals longer than max_imu_gap_s
  kImuRestarts,          // of those, longer than max_imu_bridge_s: navigation restarted
  kLateSamples,          // data older than the reorder buffer's lag: dropped
  kFutureSamples,        // a datum far ahead of all data whose own stream went back: dropped
  kDuplicateSamples,     // a sample with the time of the previous one of its sensor: dropped
  kNonFiniteSamples,     // NaN or infinite values: dropped
  kDroppedWithoutImu,    // odometer and GNSS data dropped while the IMU was silent
  kOdometerGaps,         // odometer intervals longer than max_odometer_gap_s
  kGnssGaps,             // rover epochs more than gnss_gap_warning_s (and 2.5 receiver
                         // intervals) after the previous one
  kCalibrationJumps,     // epochs at which the calibration moved beyond its chi-square gate
  kOdometerSlips,        // odometer samples left out by the factor graph's slip check
  kNumericalFailures,    // updates, solves or LAMBDA searches that failed numerically
  kSize
};

/// The counter's key in summary.json ("odometer_intervals", ...).
const char* counterName(Counter c);

/// Counter names -> tallies. Looked up by a name's characters (std::less<>): a std::string key
/// made for each look-up allocates for names over 15 characters, three times per odometer update.
using CounterMap = std::map<std::string, long, std::less<>>;

}  // namespace giocal
