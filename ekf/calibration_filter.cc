#include "ekf/calibration_filter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "common/calibration/weak_directions.h"
#include "common/gnss/spp.h"
#include "common/imu/gyro_mean.h"
#include "common/imu/imu_preintegration.h"
#include "common/math/rotation.h"
#include "common/models/heading_change_model.h"
#include "common/models/nhc_model.h"
#include "common/models/odometer_preintegration_model.h"
#include "common/models/planar_motion_projection.h"
#include "common/models/position_model.h"
#include "common/models/standstill_projection.h"
#include "common/models/zupt_model.h"
#include "ekf/imu_propagation.h"

namespace giocal {

std::array<int, 8> calibrationIndices(const StateRegistry& s) {
  std::array<int, 8> idx{};
  idx[calib_index::kSv] = s.offset(state::kSv);
  idx[calib_index::kSw] = s.offset(state::kSw);
  for (int k = 0; k < 3; ++k) {
    idx[static_cast<size_t>(calib_index::kP + k)] = s.offset(state::kPbm) + k;
    idx[static_cast<size_t>(calib_index::kTheta + k)] = s.offset(state::kQbm) + k;
  }
  return idx;
}

CalibrationFilter::CalibrationFilter(const CalibrationOptions& options,
                                     const DatasetDescription& dataset,
                                     const std::vector<ImuSample>& imu, const InitialState& init)
    : options_(options),
      dataset_(dataset),
      imu_(imu),
      frame_(init.origin_e),
      motion_(withImuNoise(options.models.motion, dataset.imu_noise.gyro_noise_density,
                           dataset.imu_noise.accel_noise_density)),
      t_(init.x.t),
      motion_fed_t_(init.x.t),
      held_states_(heldStates(options, dataset)) {
  // Navigation first, in the order of the IMU residual (p, theta, v, b_a, b_g), then calibration.
  // A copy, not a block: P may be a temporary converted from a fixed-size matrix.
  const auto blk = [](const Eigen::MatrixXd& P, int i, int n) -> Eigen::MatrixXd {
    return P.block(i, i, n, n);
  };
  const Eigen::MatrixXd Pn = init.P_nav;
  Eigen::VectorXd q(4);
  quatToWxyz(init.x.q_n_b, q.data());
  s_.add(vectorBlock(state::kP), init.x.p_n_b, blk(Pn, 0, 3));
  s_.add(rotationBlock(state::kQ), q, blk(Pn, 3, 3));
  s_.add(vectorBlock(state::kV), init.x.v_n_b, blk(Pn, 6, 3));
  s_.add(vectorBlock(state::kBa), init.x.b_a, blk(Pn, 9, 3));
  s_.add(vectorBlock(state::kBg), init.x.b_g, blk(Pn, 12, 3));
  s_.covariance().topLeftCorner(15, 15) = Pn;

  const CalibrationPrior& prior = dataset.initial_calibration;
  const Eigen::Matrix<double, 8, 8> Pc = priorCalibrationCovariance(prior);
  Eigen::VectorXd qbm(4);
  quatToWxyz(prior.mean.q_b_m, qbm.data());
  s_.add(vectorBlock(state::kSv, 1), Eigen::VectorXd::Constant(1, prior.mean.s_v), blk(Pc, 0, 1));
  s_.add(vectorBlock(state::kSw, 1), Eigen::VectorXd::Constant(1, prior.mean.s_w), blk(Pc, 1, 1));
  s_.add(vectorBlock(state::kPbm), prior.mean.p_b_m, blk(Pc, 2, 3));
  s_.add(rotationBlock(state::kQbm), qbm, blk(Pc, 5, 3));
  s_.covariance().block(15, 15, 8, 8) = Pc;
  s_.covariance().block(0, 15, 15, 8) = init.P_nav_calib;
  s_.covariance().block(15, 0, 8, 15) = init.P_nav_calib.transpose();

  const double sd_lever = options.estimate_p_b_g ? options.p_b_g_sigma : 0.0;
  s_.add(vectorBlock(state::kPbg), dataset.p_b_g,
         Eigen::Matrix3d::Identity() * sd_lever * sd_lever);
  if (options.estimate_odometer_delay) {  // about zero, after dataset.yaml's time_offsets
    const double sd = options.odometer_delay_sigma;
    s_.add(vectorBlock(state::kTdOdo, 1), Eigen::VectorXd::Zero(1),
           Eigen::MatrixXd::Constant(1, 1, sd * sd));
  }
  if (options.estimate_gyro_tilt) {
    const double sd = options.gyro_tilt_sigma_deg * kDegToRad;
    s_.add(vectorBlock(state::kGyroTilt, 2), options.gyro_tilt_start,
           Eigen::Matrix2d::Identity() * sd * sd);
  }
}

UpdateResult CalibrationFilter::updatePlanar(const MeasurementModel& model,
                                             const std::vector<StateKey>& keys, double chi2_gate,
                                             double gyro_variance, int iterations) {
  if (!options_.hold_p_b_m_z) return update(model, keys, chi2_gate, gyro_variance, iterations);
  // The projection borrows the model for this call (an empty owner: nothing allocated).
  const PlanarMotionProjection projected(
      std::shared_ptr<const MeasurementModel>(std::shared_ptr<void>(), &model));
  return update(projected, keys, chi2_gate, gyro_variance, iterations);
}

UpdateResult CalibrationFilter::updateInterval(double t) {
  interval_keys_.assign(
      {kOdoP, kOdoQ, state::kP, state::kQ, state::kSv, state::kSw, state::kPbm, state::kQbm});
  std::optional<PoseRates> rates;  // with the odometer's delay as a state
  if (options_.estimate_odometer_delay) {
    odo_rates_.v_n_j = s_.value(state::kV);
    odo_rates_.w_b_j =
        poseRate(imu_, t, s_.value(state::kBg), dataset_.imu_noise.gyro_noise_density);
    rates = odo_rates_;
    interval_keys_.push_back(state::kTdOdo);
  }
  // The models borrow the preintegration and each other for this call (empty owners).
  const OdometerPreintegrationModel model(
      std::shared_ptr<const OdometerPreintegration>(std::shared_ptr<void>(), &*odo_pre_),
      !dataset_.odom_noise.measures_yaw_rate, rates);
  const double gate = chi2Quantile(options_.chi2_probability, model.residualSize());
  if (interval_moved_) {
    return updatePlanar(model, interval_keys_, gate, 0.0, options_.odometer_iterations);
  }
  const StandstillProjection standstill(
      std::shared_ptr<const MeasurementModel>(std::shared_ptr<void>(), &model));
  return updatePlanar(standstill, interval_keys_, gate, 0.0, options_.odometer_iterations);
}

void CalibrationFilter::reopenCalibration() {
  // Adding the prior covariance keeps P positive semi-definite and the correlations; the held
  // vertical lever arm (verticalLeverState) keeps its prior variance.
  Eigen::Matrix<double, 8, 8> add = priorCalibrationCovariance(dataset_.initial_calibration);
  if (options_.hold_p_b_m_z) {
    const int v = verticalLeverState(dataset_.initial_calibration);
    add(v, v) = 0.0;
  }
  add.topLeftCorner(2, 2).setZero();
  const std::array<int, 8> idx = calibrationIndices(s_);
  double trace = 0.0;
  for (int a = 2; a < 8; ++a) {
    if (add(a, a) > 0.0) trace += s_.covariance()(idx[a], idx[a]);
  }
  if (trace >= add.trace()) return;
  for (int a = 0; a < 8; ++a)
    for (int b = 0; b < 8; ++b) s_.covariance()(idx[a], idx[b]) += add(a, b);
}

CalibrationFilter::Gyro CalibrationFilter::gyroAt(double t) const {
  const auto it = std::lower_bound(imu_.begin(), imu_.end(), t,
                                   [](const ImuSample& s, double x) { return s.t < x; });
  const double density = dataset_.imu_noise.gyro_noise_density;
  if (it == imu_.begin() || it == imu_.end()) {
    const ImuSample& s = it == imu_.end() ? imu_.back() : imu_.front();
    const double dt =
        imu_.size() > 1 ? (imu_.back().t - imu_.front().t) / double(imu_.size() - 1) : 0.01;
    return {s.gyro, density * density / dt};
  }
  const ImuSample& b = *it;
  const ImuSample& a = *(it - 1);
  const double dt = b.t - a.t, u = (t - a.t) / dt;
  // Each sample carries density^2 / dt of white noise; interpolation mixes two of them.
  return {(1.0 - u) * a.gyro + u * b.gyro,
          density * density / dt * ((1.0 - u) * (1.0 - u) + u * u)};
}

CalibrationFilter::Gyro CalibrationFilter::gyroMean(double t, double half_window) const {
  const GyroMean m = meanGyro(imu_, t, half_window, dataset_.imu_noise.gyro_noise_density);
  return {m.rate, m.variance};
}

void CalibrationFilter::feedMotion(double t) {
  const Eigen::Vector3d b_g = s_.value(state::kBg);
  auto it = std::upper_bound(imu_.begin(), imu_.end(), motion_fed_t_,
                             [](double v, const ImuSample& s) { return v < s.t; });
  for (; it != imu_.end() && it->t <= t; ++it) motion_.addImu(it->t, it->gyro - b_g, it->acc);
  motion_fed_t_ = std::max(motion_fed_t_, t);
}

const ImuPreintegration& CalibrationFilter::pendingTo(double t, bool with_covariance) {
  if (!pending_) {
    const NavState x = navState(s_);
    pending_.emplace(dataset_.imu_noise, frame_.gravity_n(x.p_n_b), frame_.omega_ie_n(), x.b_a,
                     x.b_g, gyroTilt(s_));
    pending_t_ = t_;
  }
  if (t > pending_t_) {
    pending_->addSamples(imu_, pending_t_, t);
    pending_t_ = t;
  }
  if (with_covariance) pending_->closeCovariance();
  return *pending_;
}

double CalibrationFilter::propagateTo(double t) {
  t = std::min(t, imu_.back().t);
  if (t <= t_) return 0.0;
  feedMotion(t);
  const ImuPreintegration& pre = pendingTo(t, true);
  double gap = 0.0, t_prev = t_;  // the longest IMU gap crossed
  auto it = std::upper_bound(imu_.begin(), imu_.end(), t_,
                             [](double v, const ImuSample& s) { return v < s.t; });
  for (; it != imu_.end() && it->t <= t; ++it) {
    gap = std::max(gap, it->t - t_prev);
    t_prev = it->t;
  }
  gap = std::max(gap, t - t_prev);
  propagateImu(s_, pre, propagation_);
  pending_.reset();
  const double dt = t - t_;
  const double q = options_.hold_calibration ? 0.0 : dataset_.odom_noise.scale_random_walk;
  for (const StateKey& key : {state::kSv, state::kSw}) {
    const int i = s_.offset(key);
    s_.covariance()(i, i) += q * q * dt;
  }
  t_ = t;
  return gap;
}

void CalibrationFilter::restartOdometerInterval(const OdomSample& sample) {
  // Clones of the pose now; an interval's clones are overwritten where they stand.
  s_.clone(state::kP, kOdoP);
  s_.clone(state::kQ, kOdoQ);
  odo_pre_.emplace(odometerPreintegrationNoise(
                       dataset_.odom_noise, dataset_.imu_noise.gyro_noise_density, options_.models),
                   s_.value(state::kSv)[0], s_.value(state::kSw)[0]);
  last_odo_ = sample;
  interval_moved_ = false;
  if (options_.estimate_odometer_delay) {
    odo_rates_.v_n_i = s_.value(state::kV);
    odo_rates_.w_b_i =
        poseRate(imu_, sample.t, s_.value(state::kBg), dataset_.imu_noise.gyro_noise_density);
  }
}

OdometerStep CalibrationFilter::updateOdometer(const OdomSample& sample) {
  // The covariance moves only when something updates it: the end of an odometer interval, a
  // motion constraint, or a new clone. Between those the samples are only preintegrated.
  feedMotion(sample.t);
  motion_.addOdometer(sample.t, sample.v);
  const bool still = motion_.isStatic();
  // NHC once per interval with the samples since (a stretch where it stops holding starts again).
  nhc_pending_ = motion_.nhcApplies() ? nhc_pending_ + 1 : 0;
  const bool nhc =
      nhc_pending_ > 0 && sample.t - nhc_last_t_ >= options_.models.nhc_interval_s - 1e-9;
  interval_moved_ = interval_moved_ || !still;
  const bool restart = !odo_pre_ || sample.t - last_odo_.t > options_.max_odometer_gap_s;
  const double piece = restart ? 0.0 : sample.t - last_odo_.t;
  const bool interval_done =
      !restart && odo_pre_->dt() + piece >= options_.odometer_interval_s - 1e-9;
  if (restart || interval_done || still || nhc) propagateTo(sample.t);
  OdometerStep step;
  if (restart) {
    restartOdometerInterval(sample);  // first sample, or after a gap: nothing to integrate
  } else {
    // Readings are instantaneous: the piece between two integrates their mean (trapezoid).
    if (sample.t > last_odo_.t) {
      odo_pre_->integrate(sample.t - last_odo_.t, 0.5 * (last_odo_.v + sample.v),
                          0.5 * (last_odo_.w + sample.w));
    }
    last_odo_ = sample;
    if (interval_done) {
      step.interval = true;
      step.reopened = !options_.hold_calibration &&
                      odometer_rejected_in_row_ >= options_.max_odometer_rejections;
      if (step.reopened) reopenCalibration();
      const UpdateResult r = updateInterval(sample.t);
      step.rejected = !r.accepted && !r.numerical_failure;  // a failure is not the gate's
      odometer_rejected_in_row_ =
          step.rejected && !step.reopened ? odometer_rejected_in_row_ + 1 : 0;
      restartOdometerInterval(sample);
    }
  }
  const Gyro gyro = gyroMean(sample.t, 0.5 * options_.models.motion.window_s);

  if (still) {
    static const std::vector<StateKey> kZuptKeys{state::kV};
    update(ZuptModel(options_.models.zupt_sigma), kZuptKeys,
           chi2Quantile(options_.chi2_probability, 3));
    if (!s_.has(kHeadingClone)) {
      s_.clone(state::kQ, kHeadingClone);
    } else {
      update(HeadingChangeModel(options_.heading_sigma_deg * kDegToRad), {kHeadingClone, state::kQ},
             chi2Quantile(options_.chi2_probability, 1));
    }
  } else if (s_.has(kHeadingClone)) {
    s_.remove(kHeadingClone);
  }
  if (nhc) {
    // The mean rate over the window: a single noisy sample in the lever-arm term would bias the
    // extrinsic (errors in variables).
    static const std::vector<StateKey> kNhcKeys{state::kV, state::kQ, state::kBg, state::kPbm,
                                                state::kQbm};
    updatePlanar(NhcModel(gyro.rate, options_.models.nhc_sigma / std::sqrt(nhc_pending_)), kNhcKeys,
                 chi2Quantile(options_.chi2_probability, 2), gyro.variance);
    nhc_pending_ = 0;
    nhc_last_t_ = sample.t;
  }
  return step;
}

CalibrationEstimate CalibrationFilter::calibration() const {
  CalibrationEstimate e;
  e.t = t_;
  e.calib.s_v = s_.value(state::kSv)[0];
  e.calib.s_w = s_.value(state::kSw)[0];
  e.calib.p_b_m = s_.value(state::kPbm);
  e.calib.q_b_m = quatFromWxyz(s_.value(state::kQbm).data());
  const std::array<int, 8> idx = calibrationIndices(s_);
  for (int a = 0; a < 8; ++a)
    for (int b = 0; b < 8; ++b) e.cov(a, b) = s_.covariance()(idx[a], idx[b]);
  if (options_.estimate_odometer_delay) {
    const int d = s_.offset(state::kTdOdo);
    e.odometer_delay_s = s_.value(state::kTdOdo)[0];
    e.odometer_delay_sd_s = std::sqrt(s_.covariance()(d, d));
  }
  if (s_.has(state::kGyroTilt)) {
    const int d = s_.offset(state::kGyroTilt);
    e.gyro_tilt = s_.value(state::kGyroTilt);
    e.gyro_tilt_sd = s_.covariance().block<2, 2>(d, d).diagonal().cwiseSqrt();
  }
  return e;
}

bool CalibrationFilter::updatePosition(const PositionFix& fix) {
  propagateTo(fix.t);
  const PositionModel model = positionModelOf(frame(), fix, options_.lc);
  return update(model, {state::kP, state::kQ, state::kPbg},
                chi2Quantile(options_.chi2_probability, 3))
      .accepted;
}

}  // namespace giocal
