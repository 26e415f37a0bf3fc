#include "common/online/calibrator.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "common/calibration/warm_start.h"
#include "common/calibration/weak_directions.h"
#include "common/io/text.h"
#include "common/math/rotation.h"
#include "common/odometer/gyro_yaw_rate.h"
#include "common/online/busy_timer.h"

namespace giocal {

namespace {
// A gap of more than this many of the receiver's own intervals is an outage (and of more than
// calibration.gnss_gap_warning_s); the receiver's interval is the shortest seen, judged from
// the second one on.
constexpr double kOutageIntervals = 2.5;
constexpr int kIntervalsToJudge = 2;
}  // namespace

const char* stateName(CalibratorState s) {
  switch (s) {
    case CalibratorState::kInitializing:
      return "initializing";
    case CalibratorState::kCalibrating:
      return "calibrating";
    case CalibratorState::kConverged:
      return "converged";
    case CalibratorState::kDiverged:
      return "diverged";
  }
  return "unknown";
}

Calibrator::Calibrator(std::string estimator, const DatasetDescription& dataset,
                       const Eigen::Vector3d& base_e, const CalibrationOptions& options,
                       CoreFactory factory, RunSink* sink)
    : options_(options),
      original_(dataset),
      dataset_(dataset),
      factory_(std::move(factory)),
      sink_(sink),
      reorder_(options.online.reorder_lag_s),
      convergence_(options.online.convergence, heldStates(options, dataset)),
      odometer_delay_(dataset.initial_calibration.mean.q_b_m.toRotationMatrix().col(2)) {
  if (options.estimate_odometer_delay && !dataset.odom_noise.measures_yaw_rate) {
    // Its yaw rate is the gyro's, on the IMU's clock: the delay model would shift it too.
    throw std::invalid_argument(
        "calibration.estimate_odometer_delay needs an odometer that measures its yaw rate "
        "(dataset.yaml has odometer.measures_yaw_rate: false)");
  }
  run_.estimator = std::move(estimator);
  run_.robot = robotFingerprint(dataset);
  // The component along the vehicle's vertical: p_b_m.z for an IMU mounted z up.
  const std::string vertical =
      calibrationStateName(verticalLeverState(dataset.initial_calibration));
  run_.p_b_m_z = options.hold_p_b_m_z
                     ? vertical +
                           " (the vehicle's vertical) held at the prior: planar motion leaves it "
                           "unobservable"
                     : vertical +
                           " (the vehicle's vertical) estimated; unobservable under planar motion, "
                           "its sigma stays near the prior";
  for (int c = 0; c < static_cast<int>(Counter::kSize); ++c) run_.count(Counter(c), 0);
  buf_.description = dataset;
  buf_.base_e = base_e;
  orbits_ = std::make_unique<BroadcastOrbits>(buf_.nav);
}

void Calibrator::dropped(Counter c, double t, const std::string& what) {
  noted(c, what + " at t=" + timeText(t) + " dropped");
}

void Calibrator::noted(Counter c, const std::string& what) {
  run_.count(c);
  if (warned_.insert(c).second)
    run_.warn(what + " (further ones are counted in " + counterName(c) + ")");
}

void Calibrator::addImu(const ImuSample& raw) {
  BusyTimer busy(busy_s_);
  ImuSample s = raw;
  s.t += dataset_.time_offsets.imu;  // onto GPS time: dataset.yaml's time_offsets, here only
  if (!std::isfinite(s.t) || !s.gyro.allFinite() || !s.acc.allFinite()) {
    dropped(Counter::kNonFiniteSamples, s.t, "IMU sample with NaN or infinite values");
    return;
  }
  push(s.t, {Kind::kImu, s, {}, {}, {}});
}

void Calibrator::addOdometer(const OdomSample& raw) {
  BusyTimer busy(busy_s_);
  OdomSample s = raw;
  s.t += dataset_.time_offsets.odometer;
  // A speed-only odometer's w is not read (NaN is what a driver without one sends).
  const bool w_ok = std::isfinite(s.w) || !dataset_.odom_noise.measures_yaw_rate;
  if (!std::isfinite(s.t) || !std::isfinite(s.v) || !w_ok) {
    dropped(Counter::kNonFiniteSamples, s.t, "odometer sample with NaN or infinite values");
    return;
  }
  push(s.t, {Kind::kOdometer, {}, s, {}, {}});
}

void Calibrator::addRover(const ObsEpoch& e) {
  BusyTimer busy(busy_s_);
  pushEpoch(Kind::kRover, e);
}

void Calibrator::addBase(const ObsEpoch& e) {
  BusyTimer busy(busy_s_);
  pushEpoch(Kind::kBase, e);
}

void Calibrator::pushEpoch(Kind kind, const ObsEpoch& e) {
  Datum d{kind, {}, {}, e, {}};
  const bool rover = kind == Kind::kRover;
  PhaseAlignment& phases = rover ? rover_phases_ : base_phases_;
  phases.stream(d.obs, rover ? "the rover's epochs" : "the base's epochs");
  size_t& said = rover ? rover_phases_said_ : base_phases_said_;
  for (; said < phases.warnings().size(); ++said) run_.warn(phases.warnings()[said]);
  push(e.t, std::move(d));
}

void Calibrator::addPosition(const PositionFix& raw) {
  BusyTimer busy(busy_s_);
  PositionFix p = raw;
  p.t += dataset_.time_offsets.positions;
  if (!p.p_e.allFinite() || !p.cov_enu.allFinite()) {
    dropped(Counter::kNonFiniteSamples, p.t, "position solution with NaN or infinite values");
    return;
  }
  push(p.t, {Kind::kPosition, {}, {}, {}, p});
}

void Calibrator::addEphemeris(const Ephemeris& e) { orbits_->add(e); }

void Calibrator::addNavigation(const NavData& nav) {
  orbits_->setIonosphere(nav);
  for (const Ephemeris& e : nav.ephemerides) orbits_->add(e);
  buf_.nav = orbits_->nav();
}

void Calibrator::push(double t, Datum d) {
  if (!std::isfinite(t)) {
    dropped(Counter::kNonFiniteSamples, t, "a datum with a non-finite time");
    return;
  }
  std::optional<std::pair<double, Datum>>& ahead = ahead_[static_cast<size_t>(d.kind)];
  if (ahead) {
    // The held datum's sensor speaks again: on from it, the sensor jumped; back, it was a glitch.
    std::pair<double, Datum> held = std::move(*ahead);
    ahead.reset();
    if (t >= held.first) {
      admit(held.first, std::move(held.second));
    } else {
      dropped(Counter::kFutureSamples, held.first,
              "a datum stamped " + fixedText(held.first - reorder_.newest(), 1) +
                  " s ahead of all other data, its sensor's next one back at t=" + timeText(t));
    }
  }
  if (std::isfinite(reorder_.newest()) && t > reorder_.newest() + options_.online.max_lead_s) {
    ahead.emplace(t, std::move(d));
    return;
  }
  admit(t, std::move(d));
}

void Calibrator::admit(double t, Datum d) {
  if (std::isnan(t_first_)) t_first_ = t;
  t_first_ = std::min(t_first_, t);
  if (!reorder_.push(t, std::move(d))) {
    dropped(Counter::kLateSamples, t,
            "data older than the reorder buffer's lag (online.reorder_lag_s)");
    return;
  }
  reorder_.release([&](double, Datum& x) { release(x); });
  process();
}

void Calibrator::release(Datum& d) {
  switch (d.kind) {
    case Kind::kImu: {
      const ImuSample& s = d.imu;
      if (!buf_.imu.empty() && s.t <= buf_.imu.back().t) {
        dropped(Counter::kDuplicateSamples, s.t, "IMU sample repeating the previous one's time");
        return;
      }
      const double gap = buf_.imu.empty() ? 0.0 : s.t - buf_.imu.back().t;
      if (gap > options_.max_imu_gap_s) {
        run_.count(Counter::kImuGaps);
        if (gap > options_.max_imu_bridge_s) {
          restartAfterGap(buf_.imu.back().t, s.t);
        } else {
          run_.warn("IMU gap of " + fixedText(gap, 2) +
                    " s after t=" + timeText(buf_.imu.back().t) +
                    ": bridged by interpolation, the covariance grows with it");
        }
      }
      if (std::isnan(t_imu_first_)) t_imu_first_ = s.t;
      t_imu_last_ = s.t;
      buf_.imu.push_back(s);
      odometer_delay_.addImu(s.t, s.gyro);
      frontier_ = s.t;
      break;
    }
    case Kind::kOdometer:
      if (!buf_.odom.empty() && d.odom.t <= buf_.odom.back().t) {
        dropped(Counter::kDuplicateSamples, d.odom.t,
                "odometer sample repeating the previous one's time");
        return;
      }
      if (!buf_.odom.empty() && d.odom.t - buf_.odom.back().t > options_.max_odometer_gap_s) {
        noted(Counter::kOdometerGaps, "odometer gap of " +
                                          fixedText(d.odom.t - buf_.odom.back().t, 2) +
                                          " s after t=" + timeText(buf_.odom.back().t) +
                                          " (calibration.max_odometer_gap_s): the IMU navigates "
                                          "alone through it");
      }
      if (dataset_.odom_noise.measures_yaw_rate) {
        odometer_delay_.addOdometer(d.odom.t, d.odom.w);
      } else {
        // The IMU up to this time has been released before it (time order).
        d.odom.w = gyroYawRate(buf_.imu, d.odom.t, dataset_.initial_calibration.mean,
                               core_ ? core_->nav().b_g : Eigen::Vector3d::Zero());
      }
      buf_.odom.push_back(d.odom);
      frontier_ = d.odom.t;
      break;
    case Kind::kPosition:
      if (!buf_.positions.empty() && d.position.t <= buf_.positions.back().t) {
        dropped(Counter::kDuplicateSamples, d.position.t,
                "position solution repeating the previous one's time");
        return;
      }
      frontier_ = d.position.t;
      buf_.positions.push_back(d.position);
      // Without raw GNSS the solutions are the GNSS epochs (an epoch without observations).
      if (positionsOnly()) {
        ObsEpoch epoch;
        epoch.t = d.position.t;
        acceptRover(std::move(epoch));
      }
      break;
    case Kind::kBase:
      if (!buf_.base.epochs.empty() && d.obs.t <= buf_.base.epochs.back().t) {
        dropped(Counter::kDuplicateSamples, d.obs.t,
                "base epoch repeating the previous one's time");
        return;
      }
      frontier_ = d.obs.t;
      buf_.base.epochs.push_back(std::move(d.obs));
      break;
    case Kind::kRover:
      if (d.obs.t <= last_rover_t_) {
        dropped(Counter::kDuplicateSamples, d.obs.t,
                "rover epoch repeating the previous one's time");
        return;
      }
      frontier_ = d.obs.t;
      acceptRover(std::move(d.obs));
      break;
  }
  ++released_;
}

void Calibrator::acceptRover(ObsEpoch e) {
  if (std::isfinite(last_rover_t_)) {
    // An outage is a gap beyond the receiver's own interval: a receiver logging every 30 s has
    // no outage between its epochs, it is named once instead.
    const double gap = e.t - last_rover_t_;
    rover_interval_ = std::min(rover_interval_, gap);
    ++rover_intervals_;
    if (gap > std::max(options_.gnss_gap_warning_s, kOutageIntervals * rover_interval_)) {
      noted(Counter::kGnssGaps, "no GNSS epoch for " + fixedText(gap, 1) +
                                    " s after t=" + timeText(last_rover_t_) +
                                    " (an outage, calibration.gnss_gap_warning_s): IMU and "
                                    "odometer alone through it");
    }
    if (rover_intervals_ >= kIntervalsToJudge && rover_interval_ > options_.gnss_gap_warning_s &&
        !sparse_named_) {
      sparse_named_ = true;
      run_.warn("GNSS epochs " + fixedText(rover_interval_, 1) +
                " s apart, beyond calibration.gnss_gap_warning_s: taken as the receiver's "
                "interval, not as outages; the factor graph, one state per GNSS epoch, "
                "determines yaw and s_v about 3 times less well at 30 s than at 1 s, the EKF yaw "
                "as well and s_v 1.5 times less (docs/results.md, the GNSS epoch interval)");
    }
  }
  last_rover_t_ = e.t;
  if (options_.single_receiver) {
    // Without a base the track of single point positions joined by time-differenced phase
    // stands for the fixes the initial heading is measured on.
    if (!track_) {
      track_ = std::make_unique<TdcpTrack>(*orbits_, options_.single.tdcp,
                                           options_.single.position_sigma_min_m);
    }
    if (const std::optional<PositionFix> fix = track_->add(e)) buf_.positions.push_back(*fix);
  }
  if (std::isnan(t_rover_first_)) t_rover_first_ = e.t;
  t_rover_last_ = e.t;
  rover_.push_back(std::move(e));
}

std::optional<NavState> Calibrator::navState() const {
  if (!core_) return std::nullopt;
  return core_->nav();
}

CalibratorHealth Calibrator::health() const {
  CalibratorHealth h;
  h.state = !core_ ? (diverged_ ? CalibratorState::kDiverged : CalibratorState::kInitializing)
            : convergence_.done() ? CalibratorState::kConverged
                                  : CalibratorState::kCalibrating;
  h.t_data = reorder_.newest();
  for (int k = 0; k < 8; ++k) {
    if (convergence_.takesPart(k) && convergence_.converged(k))
      h.converged.push_back(calibrationStateName(k));
  }
  if (run_.latest) {
    for (const int k : weakStates(*run_.latest, original_.initial_calibration, convergence_.held()))
      h.weak.push_back(calibrationStateName(k));
  }
  h.counters = run_.counters;
  h.buffered_samples = buf_.imu.size() + buf_.odom.size();
  h.pending_epochs = rover_.size();
  return h;
}

namespace {
constexpr long kMinEpochsToJudge = 20;   // GNSS epochs before a share of unused ones is judged
constexpr double kMaxUnusedShare = 0.2;  // a larger share of unused GNSS epochs is named
}  // namespace

void Calibrator::warnAboutUnusedGnss() {
  // Seen on the real Husky with its heights in: the factor graph kept 52 of 901 fixes, silently.
  const long unused = run_.counter(Counter::kGnssEpochsUnused);
  const long offered = unused + run_.gnss_epochs;
  if (offered < kMinEpochsToJudge ||
      static_cast<double>(unused) <= kMaxUnusedShare * static_cast<double>(offered))
    return;
  const std::string share = std::to_string(unused) + " of " + std::to_string(offered);
  if (options_.loosely_coupled) {
    run_.warn(share +
              " position fixes updated nothing (gated out, or no solution at the epoch: counter "
              "gnss_epochs_unused): where gated out, the fixes and the IMU/odometer motion "
              "disagree, and the calibration rests on the fixes kept. A "
              "receiver's height often wanders by metres (calibration.lc.use_height: 0 leaves "
              "it out); sigmas that are too small can be widened (calibration.lc.sigma_scale)");
  } else {
    run_.warn(share +
              " GNSS epochs updated nothing (no row passed the checks: counter "
              "gnss_epochs_unused): the calibration rests on the epochs kept; giocal check and "
              "gnss.csv show the satellites and fixes over time");
  }
}

}  // namespace giocal
