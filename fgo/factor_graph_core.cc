#include "fgo/factor_graph_core.h"

#include <algorithm>
#include <cmath>

#include "common/calibration/weak_directions.h"
#include "common/gnss/spp.h"
#include "common/imu/gyro_mean.h"
#include "common/imu/imu_preintegration.h"
#include "common/io/text.h"
#include "common/math/rotation.h"
#include "common/models/heading_change_model.h"
#include "common/models/imu_preintegration_model.h"
#include "common/models/nhc_model.h"
#include "common/models/planar_motion_projection.h"
#include "common/models/position_model.h"
#include "common/models/prior_model.h"
#include "common/models/random_walk_model.h"
#include "common/models/zupt_model.h"
#include "fgo/factor_tag.h"

namespace giocal {

namespace {
constexpr double kScaleRandomWalkFloor = 1e-6;  // [1/sqrt(s)]
}  // namespace

using fgo_tag::tagged;
using state::kPbg, state::kPbm, state::kQbm;

FactorGraphCore::FactorGraphCore(const CalibrationInputs& sensors, const BroadcastOrbits& orbits,
                                 const CalibrationOptions& o, const FgoOptions& fo,
                                 const InitialState& init)
    : in_(sensors),
      o_(o),
      fo_(fo),
      frame_(init.origin_e),
      orbits_(orbits),
      builder_(orbits_, sensors.base_e, o.dd),
      tdcp_(orbits_, o.single.tdcp),
      rover_check_(o.code_outliers),
      base_check_(o.code_outliers),
      motion_(withImuNoise(o.models.motion, sensors.description.imu_noise.gyro_noise_density,
                           sensors.description.imu_noise.accel_noise_density)),
      held_(heldStates(o, sensors.description)) {
  w_.setSolver(fo.solver);
  w_.setStepTolerance(fo.stop_step_sigma);
  start(init);
}

std::shared_ptr<const MeasurementModel> FactorGraphCore::planar(
    std::shared_ptr<const MeasurementModel> m) const {
  if (!o_.hold_p_b_m_z) return m;
  return std::make_shared<PlanarMotionProjection>(std::move(m));
}

void FactorGraphCore::feedMotion(double t, const Eigen::Vector3d& b_g) {
  const auto after = [&](const auto& v) {
    return std::upper_bound(v.begin(), v.end(), motion_fed_t_,
                            [](double x, const auto& s) { return x < s.t; });
  };
  auto imu = after(in_.imu);
  const auto feedImuTo = [&](double until) {
    for (; imu != in_.imu.end() && imu->t <= until; ++imu)
      motion_.addImu(imu->t, imu->gyro - b_g, imu->acc);
  };
  for (auto it = after(in_.odom); it != in_.odom.end() && it->t <= t; ++it) {
    feedImuTo(it->t);
    motion_.addOdometer(it->t, it->v);
    nhc_samples_ += motion_.nhcApplies();
  }
  feedImuTo(t);
  motion_fed_t_ = t;
}

void FactorGraphCore::start(const InitialState& init) {
  FgoEpoch e = newEpoch(init.x.t);
  const CalibrationPrior& prior = in_.description.initial_calibration;
  addNavVariables(e, init.x, prior.mean.s_v, prior.mean.s_w, 0.0);
  Eigen::VectorXd q_bm(4);
  quatToWxyz(prior.mean.q_b_m, q_bm.data());
  w_.addVariable(vectorBlock(kPbm), prior.mean.p_b_m);
  w_.addVariable(rotationBlock(kQbm), q_bm);
  w_.addVariable(vectorBlock(kPbg), in_.description.p_b_g);
  const int vertical = verticalLeverState(prior);
  if (holds(vertical)) w_.holdComponents(kPbm, {vertical - calib_index::kP});
  // The initial state and the calibration prior, with their cross-covariance (heading).
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(23, 23);
  P.topLeftCorner(15, 15) = init.P_nav;
  P.block(15, 15, 8, 8) = priorCalibrationCovariance(prior);
  P.block(0, 15, 15, 8) = init.P_nav_calib;
  P.block(15, 0, 8, 15) = init.P_nav_calib.transpose();
  std::vector<StateBlock> blocks{vectorBlock(e.p),     rotationBlock(e.q), vectorBlock(e.v),
                                 vectorBlock(e.ba),    vectorBlock(e.bg),  vectorBlock(e.sv, 1),
                                 vectorBlock(e.sw, 1), vectorBlock(kPbm),  rotationBlock(kQbm)};
  Eigen::VectorXd mean(0);
  std::vector<StateKey> keys;
  for (const StateBlock& b : blocks) {
    const Eigen::VectorXd& x = w_.value(b.key);
    mean.conservativeResize(mean.size() + x.size());
    mean.tail(x.size()) = x;
    keys.push_back(b.key);
  }
  w_.addFactor({std::make_shared<PriorModel>(blocks, mean, P), keys, 0.0, "initial_prior"});
  w_.addFactor(
      {std::make_shared<PriorModel>(std::vector<StateBlock>{vectorBlock(e.cd, 1)},
                                    Eigen::VectorXd::Zero(1), Eigen::MatrixXd::Constant(1, 1, 1e6)),
       {e.cd},
       0.0,
       "clock_drift_prior"});
  // Optional calibration states, each with an independent prior per component.
  const auto with_prior = [&](const StateKey& key, const Eigen::VectorXd& start, double sd) {
    const int n = static_cast<int>(start.size());
    if (!w_.has(key)) w_.addVariable(vectorBlock(key, n), start);
    const StateBlock b = vectorBlock(key, n);
    const Eigen::MatrixXd P_key = Eigen::MatrixXd::Identity(n, n) * sd * sd;
    w_.addFactor({std::make_shared<PriorModel>(std::vector<StateBlock>{b}, start, P_key),
                  {key},
                  0.0,
                  key.str() + "_prior"});
  };
  if (o_.estimate_p_b_g) {
    with_prior(kPbg, in_.description.p_b_g, o_.p_b_g_sigma);
  } else {
    w_.setConstant(kPbg, true);
  }
  // The odometer's delay about zero, after dataset.yaml's time_offsets.
  if (o_.estimate_odometer_delay)
    with_prior(state::kTdOdo, Eigen::VectorXd::Zero(1), o_.odometer_delay_sigma);
  if (o_.estimate_gyro_tilt)
    with_prior(state::kGyroTilt, o_.gyro_tilt_start, o_.gyro_tilt_sigma_deg * kDegToRad);
  feedMotion(e.t, init.x.b_g);
  nhc_samples_ = 0;  // samples before the start are not the first epoch's
  e.still = motion_.isStatic();
  next_output_ = e.t;
  epochs_.push_back(e);
}

CalibrationEstimate FactorGraphCore::estimate(const FgoEpoch& e) const {
  CalibrationEstimate est;
  est.t = e.t;
  est.calib.s_v = w_.value(e.sv)[0];
  est.calib.s_w = w_.value(e.sw)[0];
  est.calib.p_b_m = w_.value(kPbm);
  est.calib.q_b_m = quatFromWxyz(w_.value(kQbm).data());
  std::vector<StateKey> keys{e.sv, e.sw, kPbm, kQbm};
  if (o_.estimate_odometer_delay) keys.push_back(state::kTdOdo);
  if (o_.estimate_gyro_tilt) keys.push_back(state::kGyroTilt);
  const Eigen::MatrixXd C = w_.covariance(keys);
  est.cov = C.topLeftCorner(8, 8);
  int next = 8;
  if (o_.estimate_odometer_delay) {
    est.odometer_delay_s = w_.value(state::kTdOdo)[0];
    est.odometer_delay_sd_s = std::sqrt(C(next, next));
    ++next;
  }
  if (o_.estimate_gyro_tilt) {
    est.gyro_tilt = *gyroTilt();
    est.gyro_tilt_sd = C.block<2, 2>(next, next).diagonal().cwiseSqrt();
  }
  // A held state stays at the prior: its sigma is the prior's, and nothing correlates with it.
  const Eigen::Matrix<double, 8, 8> prior =
      priorCalibrationCovariance(in_.description.initial_calibration);
  for (int k : held_) {
    est.cov.row(k).setZero();
    est.cov.col(k).setZero();
    est.cov(k, k) = prior(k, k);
  }
  return est;
}

std::optional<GyroTilt> FactorGraphCore::gyroTilt() const {
  if (!o_.estimate_gyro_tilt) return std::nullopt;
  return GyroTilt(w_.value(state::kGyroTilt));
}

void FactorGraphCore::outputTrajectory(const FgoEpoch& from, const FgoEpoch& to) {
  const NavState x0 = nav(from);
  // One preintegration from `from`, continued to each output time (not restarted per output);
  // its mean only, as a trajectory row needs no covariance.
  ImuPreintegration pre(in_.description.imu_noise, frame_.gravity_n(x0.p_n_b), frame_.omega_ie_n(),
                        x0.b_a, x0.b_g, gyroTilt());
  pre.meanOnly();
  double integrated_to = from.t;
  while (next_output_ <= to.t + 1e-9) {
    if (next_output_ > integrated_to) pre.addSamples(in_.imu, integrated_to, next_output_);
    integrated_to = std::max(integrated_to, next_output_);
    const NavState x = next_output_ > from.t ? pre.predict(x0) : x0;
    trajectory_.push_back(truthRow(frame_, x, std::max(next_output_, from.t)));
    next_output_ += 1.0 / o_.output_rate_hz;
  }
}

void FactorGraphCore::marginalizeOldest() {
  const FgoEpoch old = epochs_.front();
  epochs_.pop_front();
  const std::vector<StateKey> mine = old.all();
  const std::set<StateKey> mine_set(mine.begin(), mine.end());
  // Ambiguities seen only by the oldest epoch's factors leave with it.
  std::set<StateKey> epoch_vars;
  for (const FgoEpoch& e : epochs_) {
    for (const StateKey& v : e.all()) epoch_vars.insert(v);
  }
  std::map<StateKey, bool> still_used;
  for (const Factor& f : w_.factors()) {
    const bool touches_old = std::any_of(f.vars.begin(), f.vars.end(),
                                         [&](const StateKey& v) { return mine_set.count(v); });
    const bool touches_epoch = std::any_of(f.vars.begin(), f.vars.end(),
                                           [&](const StateKey& v) { return epoch_vars.count(v); });
    for (const StateKey& v : f.vars) {
      if (v.what != Quantity::kAmbiguity) continue;
      still_used[v] = still_used[v] || (touches_epoch && !touches_old);
    }
  }
  std::vector<StateKey> drop = mine;
  for (const auto& [v, used] : still_used) {
    if (!used) drop.push_back(v);
  }
  for (auto it = held_fixes_.begin(); it != held_fixes_.end();) {
    const bool gone = std::find(drop.begin(), drop.end(), it->first) != drop.end() ||
                      std::find(drop.begin(), drop.end(), it->second) != drop.end();
    it = gone ? held_fixes_.erase(it) : std::next(it);
  }
  w_.marginalize(drop);
}

EpochOutcome FactorGraphCore::gnss(const ObsEpoch& rover, const ObsEpoch& base,
                                   CalibrationRun& run) {
  run_ = &run;
  const FgoEpoch prev = epochs_.back();
  FgoEpoch e = newEpoch(rover.t);
  const double dt = e.t - prev.t;
  const NavState x_prev = nav(prev);
  const bool tilted = o_.estimate_gyro_tilt;
  auto imu =
      std::make_shared<ImuPreintegration>(in_.description.imu_noise, frame_.gravity_n(x_prev.p_n_b),
                                          frame_.omega_ie_n(), x_prev.b_a, x_prev.b_g, gyroTilt());
  imu->integrateSamples(in_.imu, prev.t, e.t);
  addNavVariables(e, imu->predict(x_prev), w_.value(prev.sv)[0], w_.value(prev.sw)[0],
                  w_.value(prev.cd)[0]);
  std::vector<StateKey> imu_vars{prev.p, prev.q, prev.v, prev.ba, prev.bg,
                                 e.p,    e.q,    e.v,    e.ba,    e.bg};
  if (tilted) imu_vars.push_back(state::kGyroTilt);
  w_.addFactor(
      {std::make_shared<ImuPreintegrationModel>(imu, tilted), imu_vars, 0.0, tagged("imu", e.k)});
  // Motion constraints and whether the robot stood still over the interval.
  feedMotion(e.t, x_prev.b_g);
  e.still = motion_.isStatic();
  if (const std::vector<OdomSample> samples = intervalSamples(prev, e); !samples.empty()) {
    addOdometerFactor(prev, e, samples);
    run_->count(Counter::kOdometerIntervals);
  }
  // Scales and clock drift as random walks; the floor keeps a zero density well posed (why 1e-6:
  // docs/design.md).
  const double q_s =
      std::max(in_.description.odom_noise.scale_random_walk, kScaleRandomWalkFloor) * std::sqrt(dt);
  w_.addFactor({std::make_shared<RandomWalkModel>(state::kSv, 1, q_s), {prev.sv, e.sv}, 0.0, "rw"});
  w_.addFactor({std::make_shared<RandomWalkModel>(state::kSw, 1, q_s), {prev.sw, e.sw}, 0.0, "rw"});
  w_.addFactor({std::make_shared<RandomWalkModel>(
                    state::kClockDrift, 1, std::max(o_.clock_drift_noise, 1e-6) * std::sqrt(dt)),
                {prev.cd, e.cd},
                0.0,
                "rw"});
  if (e.still) {
    w_.addFactor({std::make_shared<ZuptModel>(o_.models.zupt_sigma), {e.v}, 0.0, "zupt"});
    if (prev.still) {
      w_.addFactor({std::make_shared<HeadingChangeModel>(o_.heading_sigma_deg * kDegToRad),
                    {prev.q, e.q},
                    0.0,
                    "heading"});
    }
  }
  if (motion_.nhcApplies()) {
    // The EKF applies NHC once per models.nhc_interval_s for the odometer samples where it holds;
    // one factor per epoch carries the information of those samples, so that both estimators
    // weigh the constraint alike.
    const GyroMean g = meanGyro(in_.imu, e.t, 0.5 * o_.models.motion.window_s,
                                in_.description.imu_noise.gyro_noise_density);
    const double sigma = o_.models.nhc_sigma / std::sqrt(std::max(1, nhc_samples_));
    w_.addFactor({planar(std::make_shared<NhcModel>(g.rate, sigma)),
                  {e.v, e.q, e.bg, kPbm, kQbm},
                  0.0,
                  "nhc"});
  }
  nhc_samples_ = 0;  // this epoch's samples only
  const PositionFix* fix = nullptr;
  if (o_.loosely_coupled) {
    fix = fixAt(in_.positions, e.t, kPositionTolerance);
    if (fix) {
      w_.addFactor({std::make_shared<PositionModel>(positionModelOf(frame_, *fix, o_.lc)),
                    {e.p, e.q, kPbg},
                    0.0,
                    tagged("position", e.k)});
    }
  } else if (o_.single_receiver) {
    singleFactors(e, prev, rover);
  } else {
    gnssFactors(e, rover, base);
    if (e.diverged) {
      run_ = nullptr;
      EpochOutcome out;
      out.diverged = true;  // the Calibrator drops this core and re-initializes
      return out;
    }
  }
  epochs_.push_back(e);
  FgoEpoch& cur = epochs_.back();
  solveWindow();
  for (int r = 0; r < fo_.max_rejections && rejectWorstRow(cur); ++r) solveWindow();
  for (int r = 0; r < fo_.max_rejections && rejectWorstTdcp(cur, epochs_[epochs_.size() - 2]); ++r)
    solveWindow();
  if (fix && rejectPosition(cur, *fix)) {
    fix = nullptr;
    solveWindow();
  }
  if (leaveOutSlips(epochs_[epochs_.size() - 2], cur)) solveWindow();
  if (rejectOdometer(cur)) solveWindow();
  EpochOutcome out;
  out.used = !o_.loosely_coupled || fix;
  out.fixed = o_.loosely_coupled ? fix && fix->quality == 1
                                 : !o_.single_receiver && o_.ambiguity_resolution && resolve(cur);
  run_->count(Counter::kDdRows, static_cast<long>(cur.code_rows.size() + cur.phase_rows.size()));
  run_->count(Counter::kTdcpRows, static_cast<long>(cur.tdcp.rows.size()));
  if (cur.doppler.size() >= 4)
    run_->count(Counter::kDopplerRows, static_cast<long>(cur.doppler.size()));
  out.recorded = true;
  out.estimate = estimate(cur);
  outputTrajectory(epochs_[epochs_.size() - 2], cur);
  if (static_cast<int>(epochs_.size()) > fo_.window) marginalizeOldest();
  run_ = nullptr;
  return out;
}

void FactorGraphCore::solveWindow() {
  const SlidingWindow::SolveReport r = w_.solve(fo_.max_iterations);
  if (r.usable && r.failure.empty()) return;
  run_->count(Counter::kNumericalFailures);
  if (run_->counter(Counter::kNumericalFailures) == 1) {
    run_->warn("the factor graph's window solve failed numerically at t=" +
               timeText(epochs_.empty() ? 0.0 : epochs_.back().t) + " (" +
               (r.failure.empty() ? std::string("not usable") : r.failure) +
               "); the window keeps its last good values (further ones are counted in "
               "numerical_failures)");
  }
}

bool FactorGraphCore::rejectPosition(const FgoEpoch& e, const PositionFix& fix) {
  // As the EKF's gate, on the solved window: a solution this far off (a wrong fix under trees)
  // leaves the window instead of pulling it.
  const PositionModel model = positionModelOf(frame_, fix, o_.lc);
  const double* params[3] = {w_.value(e.p).data(), w_.value(e.q).data(), w_.value(kPbg).data()};
  Eigen::VectorXd r;
  model.evaluate(params, r, nullptr);
  if (r.dot(model.covariance().ldlt().solve(r)) <= chi2Quantile(o_.chi2_probability, 3))
    return false;
  w_.removeFactors(tagged("position", e.k));
  run_->count(Counter::kGnssRowsRejected, 3);
  return true;
}

void FactorGraphCore::trajectoryUpTo(double t, const std::function<void(const TruthSample&)>& out) {
  size_t n = 0;
  while (n < trajectory_.size() && trajectory_[n].t <= t + 1e-9) out(trajectory_[n++]);
  trajectory_.erase(trajectory_.begin(), trajectory_.begin() + static_cast<long>(n));
}

double FactorGraphCore::oldestSampleNeeded() const {
  // The trajectory is predicted from the epoch before the newest; the motion detectors and the
  // mean gyro look half a window around an epoch.
  return epochs_.front().t - o_.models.motion.window_s;
}

}  // namespace giocal
