#include "ekf/calibration_filter.h"

#include <algorithm>
#include <cmath>

#include "common/gnss/spp.h"
#include "common/imu/imu_preintegration.h"
#include "common/math/rotation.h"
#include "common/models/heading_change_model.h"
#include "common/models/nhc_model.h"
#include "common/models/odometer_velocity_model.h"
#include "common/models/zupt_model.h"
#include "ekf/imu_propagation.h"

namespace giocal {
namespace {

MotionDetectorOptions detectorOptions(const CalibrationOptions& o, const ImuNoise& noise) {
  MotionDetectorOptions m = o.models.motion;
  m.gyro_noise_density = noise.gyro_noise_density;
  return m;
}

}  // namespace

CalibrationFilter::CalibrationFilter(const CalibrationOptions& options,
                                     const DatasetDescription& dataset,
                                     const std::vector<ImuSample>& imu, const InitialState& init)
    : options_(options),
      dataset_(dataset),
      imu_(imu),
      frame_(init.origin_e),
      motion_(detectorOptions(options, dataset.imu_noise)),
      t_(init.x.t),
      chi2_odometer_(chi2Quantile(options.chi2_probability, 2)) {
  // Navigation first, in the order of the IMU residual (p, theta, v, b_a, b_g), then calibration.
  const auto blk = [](const Eigen::MatrixXd& P, int i, int n) { return P.block(i, i, n, n); };
  const Eigen::MatrixXd Pn = init.P_nav;
  Eigen::VectorXd q(4);
  quatToWxyz(init.x.q_n_b, q.data());
  s_.add(vectorBlock(nav_var::kP), init.x.p_n_b, blk(Pn, 0, 3));
  s_.add(rotationBlock(nav_var::kQ), q, blk(Pn, 3, 3));
  s_.add(vectorBlock(nav_var::kV), init.x.v_n_b, blk(Pn, 6, 3));
  s_.add(vectorBlock(nav_var::kBa), init.x.b_a, blk(Pn, 9, 3));
  s_.add(vectorBlock(nav_var::kBg), init.x.b_g, blk(Pn, 12, 3));
  s_.covariance().topLeftCorner(15, 15) = Pn;

  const CalibrationPrior& prior = dataset.initial_calibration;
  const Eigen::Matrix<double, 8, 8> Pc = priorCalibrationCovariance(prior);
  Eigen::VectorXd qbm(4);
  quatToWxyz(prior.mean.q_b_m, qbm.data());
  s_.add(vectorBlock(block::kSv, 1), Eigen::VectorXd::Constant(1, prior.mean.s_v), blk(Pc, 0, 1));
  s_.add(vectorBlock(block::kSw, 1), Eigen::VectorXd::Constant(1, prior.mean.s_w), blk(Pc, 1, 1));
  s_.add(vectorBlock(block::kPbm), prior.mean.p_b_m, blk(Pc, 2, 3));
  s_.add(rotationBlock(block::kQbm), qbm, blk(Pc, 5, 3));
  s_.covariance().block(15, 15, 8, 8) = Pc;
  s_.covariance().block(0, 15, 15, 8) = init.P_nav_calib;
  s_.covariance().block(15, 0, 8, 15) = init.P_nav_calib.transpose();

  const double sd_lever = options.estimate_p_b_g ? options.p_b_g_sigma : 0.0;
  s_.add(vectorBlock(ekf_var::kPbg), dataset.p_b_g,
         Eigen::Matrix3d::Identity() * sd_lever * sd_lever);
}

std::vector<int> CalibrationFilter::heldIndices() const {
  if (!options_.hold_p_b_m_z) return {};
  return {s_.offset(block::kPbm) + 2};
}

UpdateResult CalibrationFilter::update(const MeasurementModel& model,
                                       const std::vector<std::string>& names, double chi2_gate) {
  const MeasurementRows rows = linearize(model, s_.bind(names), s_.dim());
  const UpdateResult r = kalmanUpdate(s_.covariance(), rows, chi2_gate, heldIndices());
  if (r.accepted) s_.correct(r.dx);
  return r;
}

Eigen::Vector3d CalibrationFilter::gyroAt(double t) const {
  const auto it = std::lower_bound(imu_.begin(), imu_.end(), t,
                                   [](const ImuSample& s, double x) { return s.t < x; });
  if (it == imu_.begin()) return imu_.front().gyro;
  if (it == imu_.end()) return imu_.back().gyro;
  const ImuSample& b = *it;
  const ImuSample& a = *(it - 1);
  const double u = (t - a.t) / (b.t - a.t);
  return (1.0 - u) * a.gyro + u * b.gyro;
}

double CalibrationFilter::propagateTo(double t) {
  t = std::min(t, imu_.back().t);
  if (t <= t_) return 0.0;
  const NavState x = navState(s_);
  ImuPreintegration pre(dataset_.imu_noise, frame_.gravity_n(x.p_n_b), frame_.omega_ie_n(), x.b_a,
                        x.b_g);
  pre.integrateSamples(imu_, t_, t);
  // The motion detector sees every bias-compensated sample; note the longest gap crossed.
  double gap = 0.0, t_prev = t_;
  auto it = std::upper_bound(imu_.begin(), imu_.end(), t_,
                             [](double v, const ImuSample& s) { return v < s.t; });
  for (; it != imu_.end() && it->t <= t; ++it) {
    motion_.addImu(it->t, it->gyro - x.b_g);
    gap = std::max(gap, it->t - t_prev);
    t_prev = it->t;
  }
  gap = std::max(gap, t - t_prev);
  propagateImu(s_, pre);
  const double dt = t - t_;
  const double q = dataset_.odom_noise.scale_random_walk;
  for (const char* name : {block::kSv.c_str(), block::kSw.c_str()}) {
    const int i = s_.offset(name);
    s_.covariance()(i, i) += q * q * dt;
  }
  t_ = t;
  return gap;
}

bool CalibrationFilter::updateOdometer(const OdomSample& sample) {
  propagateTo(sample.t);
  const Eigen::Vector3d gyro = gyroAt(sample.t);
  motion_.addOdometer(sample.t, sample.v);
  const OdometerNoise& on = dataset_.odom_noise;
  const OdometerVelocityModel odo(sample, gyro, on.speed_sigma, on.yaw_rate_sigma);
  const UpdateResult r =
      update(odo,
             {nav_var::kV, nav_var::kQ, nav_var::kBg, block::kSv, block::kSw, block::kPbm,
              block::kQbm},
             chi2_odometer_);

  if (motion_.isStatic()) {
    update(ZuptModel(options_.models.zupt_sigma), {nav_var::kV},
           chi2Quantile(options_.chi2_probability, 3));
    if (!s_.has(ekf_var::kHeadingClone)) {
      s_.clone(nav_var::kQ, ekf_var::kHeadingClone);
    } else {
      update(HeadingChangeModel(options_.heading_sigma_deg * kDegToRad),
             {ekf_var::kHeadingClone, nav_var::kQ}, chi2Quantile(options_.chi2_probability, 1));
    }
  } else if (s_.has(ekf_var::kHeadingClone)) {
    s_.remove(ekf_var::kHeadingClone);
  }
  if (motion_.nhcApplies()) {
    update(NhcModel(gyro, options_.models.nhc_sigma),
           {nav_var::kV, nav_var::kQ, nav_var::kBg, block::kPbm, block::kQbm},
           chi2Quantile(options_.chi2_probability, 2));
  }
  return r.accepted;
}

NavState CalibrationFilter::nav() const {
  NavState x = navState(s_);
  x.t = t_;
  return x;
}

CalibrationEstimate CalibrationFilter::calibration() const {
  CalibrationEstimate e;
  e.t = t_;
  e.calib.s_v = s_.value(block::kSv)[0];
  e.calib.s_w = s_.value(block::kSw)[0];
  e.calib.p_b_m = s_.value(block::kPbm);
  e.calib.q_b_m = quatFromWxyz(s_.value(block::kQbm).data());
  const int idx[4] = {s_.offset(block::kSv), s_.offset(block::kSw), s_.offset(block::kPbm),
                      s_.offset(block::kQbm)};
  const int start[4] = {calib_index::kSv, calib_index::kSw, calib_index::kP, calib_index::kTheta};
  const int size[4] = {1, 1, 3, 3};
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      e.cov.block(start[a], start[b], size[a], size[b]) =
          s_.covariance().block(idx[a], idx[b], size[a], size[b]);
  return e;
}

TruthSample CalibrationFilter::trajectorySample() const {
  const NavState x = nav();
  TruthSample s;
  s.t = t_;
  const Eigen::Vector3d p_e = frame_.ecefFromEnu(x.p_n_b);
  const Geodetic g = geodeticFromEcef(p_e);
  s.lat_deg = g.lat * kRadToDeg;
  s.lon_deg = g.lon * kRadToDeg;
  s.h = g.h;
  // truth.csv uses the local-level ENU frame at the current position.
  const Eigen::Matrix3d R_here_n = rotationEcefFromEnu(g.lat, g.lon).transpose() * frame_.R_e_n();
  s.v_enu = R_here_n * x.v_n_b;
  s.q_n_b = Eigen::Quaterniond(R_here_n * x.q_n_b.toRotationMatrix()).normalized();
  return s;
}

}  // namespace giocal
