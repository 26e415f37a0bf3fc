// The end of a Calibrator's run: the buffers drained, the last estimate taken, and what the run
// found said: weak directions, rejected and unused data, numerical failures, the odometer's
// measured delay, and the status (ok, partial or suspect).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/calibration/rejection_share.h"
#include "common/calibration/weak_directions.h"
#include "common/io/text.h"
#include "common/online/busy_timer.h"
#include "common/online/calibrator.h"

namespace giocal {

namespace {
// An odometer delay is worth a word when it is this large and known this well [s].
constexpr double kDelayToTell = 0.01;
constexpr double kDelaySigmaToTell = 0.01;
constexpr double kDelayFirstOrder = 0.1;  // [s] the delay state's first-order model
}  // namespace

void Calibrator::finish() {
  BusyTimer busy(busy_s_);
  finishing_ = true;
  for (auto& ahead : ahead_) {  // no next datum of its sensor came to confirm the jump
    if (ahead) {
      dropped(Counter::kFutureSamples, ahead->first,
              "the last datum of a sensor, stamped " +
                  fixedText(ahead->first - reorder_.newest(), 1) + " s ahead of all other data");
    }
    ahead.reset();
  }
  reorder_.release([&](double, Datum& x) { release(x); }, true);
  process();
  const std::string why = why_not_initialized_.empty()
                              ? std::string("no rover epoch with IMU and odometer data around it")
                              : why_not_initialized_;
  if (!core_ && run_.latest) {
    run_.warn("no re-initialization possible after t=" + timeText(t_from_) + ": " + why);
    run_.status = "partial: " + std::string(diverged_ ? "the estimator diverged" : "an IMU gap") +
                  " before t=" + timeText(t_from_) +
                  " and the data after it allow no new initial state (" + why +
                  "); the calibration is the last one before it";
  } else if (!core_) {
    if (!diverged_) {
      throw std::runtime_error("could not initialize: " + why);
    }
    run_.warn("no re-initialization possible after t=" + timeText(t_from_) + ": " + why);
  }
  if (core_ && (!run_.latest || run_.latest->t < core_->time())) onEstimate(core_->calibration());
  if (run_.latest) {
    for (const std::string& w :
         weakDirections(*run_.latest, original_.initial_calibration, convergence_.held()))
      run_.warn(w);
  }
  // In the LC scheme the GNSS rows are the positions, with or without raw GNSS beside them.
  const bool position_rows = positionsOnly() || options_.loosely_coupled;
  for (const std::string& w : rejectionShareWarnings(run_, position_rows)) run_.warn(w);
  warnAboutUnusedGnss();
  if (options_.single_receiver) warnAboutSingleReceiverRows();
  if (const long n = run_.counter(Counter::kNumericalFailures); n > 0) {
    run_.warn(std::to_string(n) +
              " updates, solves or ambiguity searches failed numerically (counter "
              "numerical_failures; not gate rejections): the estimator skipped them, and the "
              "calibration rests on the rest");
  }
  // `ok` means the run believes its answer; one whose estimate has left its data does not.
  const std::string suspect = suspectReason(run_, position_rows, options_.loosely_coupled);
  if (run_.status == "ok" && !suspect.empty()) run_.status = "suspect: " + suspect;
  if (!dataset_.odom_noise.measures_yaw_rate) {
    const CalibrationPrior& p = original_.initial_calibration;
    run_.warn(
        "s_w is not calibrated: the odometer measures speed only (odometer.measures_yaw_rate: "
        "false in dataset.yaml); it keeps the initial guess " +
        fixedText(p.mean.s_w, 4) + " +- " + fixedText(p.sd_s_w, 4));
  }
  run_.odometer_delay = odometer_delay_.estimate();
  const OdometerDelay& d = run_.odometer_delay;
  const bool estimated = run_.latest && std::isfinite(run_.latest->odometer_delay_s);
  if (estimated && std::abs(run_.latest->odometer_delay_s) > kDelayFirstOrder) {
    const double t_d = run_.latest->odometer_delay_s;
    run_.warn("the estimated odometer delay (" + fixedText(1e3 * t_d, 0) + " ms) is beyond the " +
              fixedText(1e3 * kDelayFirstOrder, 0) +
              " ms its first-order model holds: set time_offsets: {odometer: " +
              fixedText(dataset_.time_offsets.odometer - t_d, 3) + "} in dataset.yaml");
  } else if (estimated && d.valid &&
             std::abs(run_.latest->odometer_delay_s - d.delay_s) >
                 3.0 * std::hypot(run_.latest->odometer_delay_sd_s, d.sigma_s)) {
    // Seen on the real Husky: the state stayed at zero whatever offset was set, the yaw rates
    // followed it (docs/results.md). The yaw-rate measure is direct; the state is a model.
    const double t_d = run_.latest->odometer_delay_s;
    run_.warn("the odometer's delay as a calibration state (" + fixedText(1e3 * t_d, 0) + " +- " +
              fixedText(1e3 * run_.latest->odometer_delay_sd_s, 0) +
              " ms) disagrees with the one the yaw rates show (" + fixedText(1e3 * d.delay_s, 0) +
              " +- " + fixedText(1e3 * d.sigma_s, 0) +
              " ms): its model does not fit this odometer; set time_offsets: {odometer: " +
              fixedText(dataset_.time_offsets.odometer - d.delay_s, 3) +
              "} in dataset.yaml and calibrate without the state");
  } else if (!estimated && d.valid && d.sigma_s < kDelaySigmaToTell &&
             std::abs(d.delay_s) > kDelayToTell && std::abs(d.delay_s) > 3.0 * d.sigma_s) {
    run_.warn("the odometer's stamps are " + fixedText(1e3 * std::abs(d.delay_s), 0) + " +- " +
              fixedText(1e3 * d.sigma_s, 0) + " ms " + (d.delay_s > 0 ? "late" : "early") +
              " against the IMU's (the yaw rate both measure): set time_offsets: {odometer: " +
              fixedText(dataset_.time_offsets.odometer - d.delay_s, 3) + "} in dataset.yaml");
  }
  run_.t_first_rover_epoch = t_rover_first_;
  if (!std::isnan(t_imu_first_) && !std::isnan(t_rover_first_)) {
    run_.data_duration_s = std::max(
        0.0, std::min(t_imu_last_, t_rover_last_) - std::max(t_imu_first_, t_rover_first_));
  }
  run_.timing["initialization_s"] = init_time_s_;
  run_.timing["gnss_epoch_mean_s"] = latency_.mean();
  run_.timing["gnss_epoch_p50_s"] = latency_.percentile(0.5);
  run_.timing["gnss_epoch_p99_s"] = latency_.percentile(0.99);
  run_.timing["gnss_epoch_max_s"] = latency_.max();
  // The calibrator's own time: what the sink does with the results (writing the output files,
  // checking fixes against a truth file) is the caller's, reported apart.
  run_.timing["outputs_s"] = sink_s_;
  run_.wall_time_s = busy_s_ - sink_s_;
}

void Calibrator::warnAboutSingleReceiverRows() {
  // One receiver runs with what its file has; a kind of row it never had is said, with what the
  // calibration then rests on.
  const long tdcp = run_.counter(Counter::kTdcpRows), doppler = run_.counter(Counter::kDopplerRows);
  if (run_.gnss_epochs == 0) return;
  if (tdcp == 0) {
    run_.warn(
        std::string("no time-differenced carrier phase rows (the rover file has no usable "
                    "carrier phase, or it slipped at every epoch): the calibration rests on ") +
        (doppler > 0 ? "Doppler and single point positions" : "single point positions") +
        ", metres-coarse");
  }
  if (doppler == 0) {
    run_.warn(
        "no Doppler rows (the rover file has no Doppler, or too few satellites): the "
        "velocity comes from the carrier phase and the single point positions alone");
  }
}

}  // namespace giocal
