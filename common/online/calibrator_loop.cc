// The Calibrator's event loop: initialization attempts as data arrive, odometer and GNSS events
// handed to the estimator core in time order once the data around them are complete,
// re-initialization after a divergence, live reports, trimming of the buffers. (The input side,
// reordering and bad data, is in calibrator.cc; the end of a run in calibrator_finish.cc.)
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/calibration/reinitialization_prior.h"
#include "common/calibration/rejection_share.h"
#include "common/calibration/weak_directions.h"
#include "common/geodesy/wgs84.h"
#include "common/gnss/sky_view.h"
#include "common/gnss/spp.h"
#include "common/io/text.h"
#include "common/math/rotation.h"
#include "common/online/busy_timer.h"
#include "common/online/calibrator.h"

namespace giocal {
namespace {

/// Drops the samples before t but the last one before it (interpolation needs it), once they are
/// at least half the buffer (amortized constant cost per sample).
template <class T>
void dropBefore(std::vector<T>& v, double t) {
  auto it = std::lower_bound(v.begin(), v.end(), t, [](const T& s, double x) { return s.t < x; });
  if (it != v.begin()) --it;
  if (2 * (it - v.begin()) >= static_cast<long>(v.size())) v.erase(v.begin(), it);
}

}  // namespace

bool Calibrator::ready(double t) const {
  if (finishing_ || t <= flush_until_) return true;
  // Events read ahead: the motion detectors' half window, the base epoch nearest in time.
  const double look =
      std::max(0.5 * options_.models.motion.window_s, options_.max_base_offset) + 0.05;
  if (frontier_ < t + look) return false;
  return (!buf_.imu.empty() && buf_.imu.back().t > t) ||
         frontier_ >= t + options_.online.max_imu_wait_s;
}

const ObsEpoch* Calibrator::nearestBase(double t) const {
  const auto& b = buf_.base.epochs;
  auto it =
      std::lower_bound(b.begin(), b.end(), t, [](const ObsEpoch& e, double x) { return e.t < x; });
  const ObsEpoch* best = nullptr;
  if (it != b.end()) best = &*it;
  // Ties go to the later epoch, as BaseEpochMatcher does.
  if (it != b.begin() && (!best || t - (it - 1)->t < best->t - t)) best = &*(it - 1);
  return best && std::abs(best->t - t) <= options_.max_base_offset ? best : nullptr;
}

bool Calibrator::tryInitialize() {
  if (buf_.imu.size() < 2 || buf_.odom.empty()) return false;
  // The epochs an attempt reads are kept between attempts and only the new ones appended:
  // copying them all again for every attempt cost a tenth of a whole run (callgrind).
  std::vector<ObsEpoch>& epochs = buf_.rover.epochs;
  const auto stale =
      std::find_if(epochs.begin(), epochs.end(), [&](const ObsEpoch& e) { return e.t >= t_from_; });
  epochs.erase(epochs.begin(), stale);
  const double newest = epochs.empty() ? -INFINITY : epochs.back().t;
  for (size_t k = 0; k < rover_.size(); ++k) {
    const ObsEpoch& e = rover_[k];
    if (!ready(e.t) || e.t > buf_.imu.back().t) break;
    if (e.t >= t_from_ && e.t > newest) epochs.push_back(e);
  }
  // Nothing new since the last attempt (the attempt depends only on complete data before it).
  if (epochs.empty() || epochs.back().t <= last_init_try_) return false;
  last_init_try_ = epochs.back().t;
  buf_.description = dataset_;
  buf_.nav = orbits_->nav();
  const auto t0 = std::chrono::steady_clock::now();
  std::string why;
  const auto init = findInitialState(buf_, options_, dataset_.initial_calibration,
                                     std::max(t_from_, buf_.imu.front().t), &why, &init_cache_);
  init_time_s_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!init) {
    why_not_initialized_ = why;
    if (frontier_ - std::max(t_from_, buf_.imu.front().t) > options_.online.max_init_window_s) {
      t_from_ = frontier_ - 0.5 * options_.online.max_init_window_s;
      run_.warn("no initial state in " + fixedText(options_.online.max_init_window_s, 0) +
                " s of data (" + why + "); searching on from t=" + timeText(t_from_));
    }
    return false;
  }
  const bool again = !run_.initialization.empty();
  if (!again) {
    run_.t_initialized = init->x.t;
    run_.initialization = {{"static_window_s", init->static_window_s},
                           {"heading_baseline_m", init->heading_baseline_m},
                           {"heading_sigma_deg", init->heading_sigma * kRadToDeg},
                           {"b_g_z_deg_h", init->x.b_g.z() * kRadToDeg * 3600.0}};
  }
  epochs.clear();  // the estimator takes rover epochs from the stream, not from here
  core_ = factory_(buf_, *orbits_, *init);
  core_estimate_.reset();
  origin_e_ = init->origin_e;
  init_cache_ = {};
  why_not_initialized_.clear();
  diverged_ = false;
  say(init->x.t, std::string(again ? "re-" : "") + "initialized: heading from a " +
                     fixedText(init->heading_baseline_m, 1) + " m baseline, static window " +
                     fixedText(init->static_window_s, 1) + " s");
  return true;
}

void Calibrator::process() {
  while (true) {
    if (!core_) {
      if (!tryInitialize()) break;
      continue;
    }
    double t_odo = INFINITY;
    auto odo = buf_.odom.end();
    if (core_->takesOdometerEvents()) {
      // The next odometer sample after both the last one handed over and the state's time.
      const double after = std::max(last_odo_event_, core_->time());
      odo = std::upper_bound(buf_.odom.begin(), buf_.odom.end(), after,
                             [](double x, const OdomSample& s) { return x < s.t; });
      if (odo != buf_.odom.end()) t_odo = odo->t;
    }
    const double t_rover = rover_.empty() ? INFINITY : rover_.front().t;
    const double t_next = std::min(t_odo, t_rover);
    if (!std::isfinite(t_next) || !ready(t_next)) break;
    const bool is_odo = t_odo <= t_rover;
    if (buf_.imu.empty() || buf_.imu.back().t < t_next) {
      if (finishing_) {  // past the last IMU sample: nothing more to process
        rover_.clear();
        last_odo_event_ = INFINITY;
        break;
      }
      dropped(Counter::kDroppedWithoutImu, t_next,
              "odometer or GNSS data with the IMU silent for online.max_imu_wait_s");
      if (is_odo) {
        last_odo_event_ = t_odo;
      } else {
        rover_.pop_front();
      }
      continue;
    }
    if (is_odo) {
      last_odo_event_ = t_odo;
      core_->odometer(*odo, run_);
      core_->trajectoryUpTo(
          t_odo, [&](const TruthSample& s) { toSink([&](RunSink& sink) { sink.trajectory(s); }); });
    } else {
      const ObsEpoch rover = std::move(rover_.front());
      rover_.pop_front();
      dispatchRover(rover);
    }
  }
  trim();
}

void Calibrator::dispatchRover(const ObsEpoch& rover) {
  if (rover.t <= skip_rover_until_ || !core_->acceptsEpoch(rover.t)) return;
  static const ObsEpoch kNoBase;  // the LC and single-receiver schemes read no base epoch
  const ObsEpoch* base =
      positionsOnly() || options_.single_receiver ? &kNoBase : nearestBase(rover.t);
  if (!base) {
    noted(Counter::kGnssWithoutBase, "the rover epoch at t=" + timeText(rover.t) +
                                         " has no base epoch within calibration.max_base_offset: "
                                         "skipped");
    return;
  }
  const auto t0 = std::chrono::steady_clock::now();
  const EpochOutcome out = core_->gnss(rover, *base, run_);
  latency_.add(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  if (out.diverged) {
    run_.warn("the estimator diverged at t=" + timeText(rover.t) +
              " (GNSS code far outside its predicted spread); re-initializing");
    run_.count(Counter::kReinitializations);
    say(rover.t, "diverged; re-initializing from the data that follow");
    dataset_ = reinitializationPrior(original_, core_->calibration());
    core_.reset();
    diverged_ = true;
    t_from_ = rover.t;
    last_init_try_ = -INFINITY;
    skip_rover_until_ = rover.t;
    rover_.insert(0, rover);
    return;
  }
  if (out.used) {
    ++run_.gnss_epochs;
    run_.fixed_epochs += out.fixed;
  } else {
    run_.count(Counter::kGnssEpochsUnused);
  }
  toSink([&](RunSink& sink) {
    SkyView sky;
    const LocalFrame frame(origin_e_);
    const NavState& x = core_->nav();
    if (!positionsOnly()) {
      sky = skyView(rover, *orbits_, frame.ecefFromEnu(x.p_n_b), options_.dd.elevation_mask_deg);
    }
    const Eigen::Vector3d antenna_e = frame.ecefFromEnu(x.p_n_b + x.q_n_b * dataset_.p_b_g);
    sink.gnssEpoch({rover.t, sky.satellites, sky.pdop, out.used, out.fixed, antenna_e});
  });
  if (out.recorded) onEstimate(out.estimate);
  core_->trajectoryUpTo(
      rover.t, [&](const TruthSample& s) { toSink([&](RunSink& sink) { sink.trajectory(s); }); });
}

void Calibrator::onEstimate(const CalibrationEstimate& e) {
  run_.latest = e;
  if (core_estimate_) {
    const double step = calibrationStepChi2(*core_estimate_, e);
    if (step > chi2Quantile(options_.chi2_probability, 7)) {
      noted(Counter::kCalibrationJumps,
            "the calibration moved further in one epoch than one epoch's data can move it "
            "(chi-square " +
                fixedText(step, 0) + " in its sigmas before, at t=" + timeText(e.t) +
                "): the data before or after disagree with the model (wheel slip, a wrong fix, "
                "wrong noise, lever arm or time offsets in dataset.yaml), and the estimate may "
                "have left the truth");
    }
  }
  core_estimate_ = e;
  toSink([&](RunSink& sink) { sink.estimate(e); });
  for (const ConvergenceEvent& c : convergence_.update(e)) {
    const std::string name = calibrationStateName(c.state);
    if (c.converged) run_.converged_at[name] = rel(c.t);
    say(c.t, name + (c.converged ? " converged: " : " no longer converged: ") +
                 fixedText(c.value, c.state < 2   ? 5
                                    : c.state < 5 ? 4
                                                  : 3) +
                 " +- " +
                 fixedText(c.sigma, c.state < 2   ? 5
                                    : c.state < 5 ? 4
                                                  : 3) +
                 calibrationStateUnit(c.state));
  }
  if (convergence_.done() && !done_said_) {
    done_said_ = true;
    run_.converged_at["calibration"] = rel(e.t);
    say(e.t, "calibration converged: every observable parameter is steady within its target");
  }
  if (std::isnan(next_progress_)) next_progress_ = e.t + options_.online.progress_interval_s;
  if (e.t >= next_progress_ && !convergence_.done()) {
    next_progress_ += options_.online.progress_interval_s;
    std::string open, weak;
    for (int k = 0; k < 8; ++k) {
      if (convergence_.takesPart(k) && !convergence_.converged(k))
        open += std::string(open.empty() ? "" : ", ") + calibrationStateName(k);
    }
    // Each with the motion that would inform it (as `giocal observability` advises).
    for (const int k : weakStates(e, original_.initial_calibration, convergence_.held())) {
      weak += std::string("; still near the prior: ") + calibrationStateName(k) + " (needs " +
              motionThatInforms(k) + ")";
    }
    say(e.t, "not converged yet: " + open + weak);
  }
}

void Calibrator::say(double t, const std::string& text) {
  toSink([&](RunSink& sink) { sink.event(rel(t), text); });
}

void Calibrator::trim() {
  if (released_ % 64 != 0) return;
  const double margin = std::max(5.0, 2.0 * options_.models.motion.window_s);
  double keep = t_from_;
  if (core_) {
    keep = core_->oldestSampleNeeded();
    if (!rover_.empty()) keep = std::min(keep, rover_.front().t);
  }
  keep -= margin;
  dropBefore(buf_.imu, keep);
  dropBefore(buf_.odom, keep);
  dropBefore(buf_.base.epochs, keep - options_.max_base_offset);
  dropBefore(buf_.positions, keep - 1.0);
  if (!core_) {  // initializing: rover epochs before the search window are of no use
    while (!rover_.empty() && rover_.front().t < t_from_) rover_.pop_front();
  }
}

void Calibrator::restartAfterGap(double t0, double t1) {
  run_.count(Counter::kImuRestarts);
  run_.warn("IMU gap of " + fixedText(t1 - t0, 2) + " s after t=" + timeText(t0) +
            ": longer than calibration.max_imu_bridge_s; the navigation state restarts from the "
            "data after it, the calibration is carried over with its covariance");
  if (core_) {
    flush_until_ = t0;  // the events the IMU covers are complete: finish them
    process();
    flush_until_ = -INFINITY;
  }
  if (core_) {
    const CalibrationEstimate e = core_->calibration();
    if (!run_.latest || run_.latest->t < core_->time()) onEstimate(e);
    dataset_ = original_;
    dataset_.initial_calibration.mean = e.calib;
    dataset_.initial_calibration.covariance = e.cov;
    core_.reset();
    say(t0, "IMU gap of " + fixedText(t1 - t0, 1) + " s: restarting after it");
  }
  t_from_ = std::max(t_from_, t1);
  last_init_try_ = -INFINITY;
  init_cache_ = {};
}

}  // namespace giocal
