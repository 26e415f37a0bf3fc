#include "common/calibration/initial_state.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "common/calibration/calibration_run.h"
#include "common/gnss/broadcast_orbits.h"
#include "common/gnss/rtk.h"
#include "common/imu/static_alignment.h"
#include "common/io/text.h"
#include "common/math/rotation.h"
#include "common/math/so3.h"

namespace giocal {
namespace {

/// A GNSS antenna position good enough to measure a displacement.
struct AntennaFix {
  double t = 0.0;
  Eigen::Vector3d p_e = Eigen::Vector3d::Zero();
  double sd_h = 0.0;                                // horizontal 1-sigma [m]
  Eigen::Matrix3d cov_n = Eigen::Matrix3d::Zero();  // RTK: the solution's covariance in n [m^2]
};

/// The first run of odometer samples from t_from on with the wheels still, [t0, t1]: the mean
/// speed and yaw rate over a centred window below the thresholds (the readings themselves are
/// noisy). The run's end is pulled in by half a window so no motion leaks into it.
std::pair<double, double> firstStaticRun(const std::vector<OdomSample>& odom, double t_from,
                                         double max_speed, double window) {
  constexpr double kMaxYawRate = 1.0 * kDegToRad;
  const size_t n = odom.size();
  std::vector<double> sv(n + 1, 0.0), sw(n + 1, 0.0);
  for (size_t k = 0; k < n; ++k) {
    sv[k + 1] = sv[k] + odom[k].v;
    sw[k + 1] = sw[k] + odom[k].w;
  }
  double t0 = NAN, t1 = NAN;
  size_t lo = 0, hi = 0;
  for (size_t k = 0; k < n; ++k) {
    if (odom[k].t < t_from) continue;
    while (lo < k && odom[lo].t < odom[k].t - 0.5 * window) ++lo;
    while (hi < n && odom[hi].t <= odom[k].t + 0.5 * window) ++hi;
    const double cnt = static_cast<double>(hi - lo);
    const bool still = std::abs(sv[hi] - sv[lo]) / cnt < max_speed &&
                       std::abs(sw[hi] - sw[lo]) / cnt < kMaxYawRate;
    if (still) {
      if (std::isnan(t0)) t0 = odom[k].t;
      t1 = odom[k].t;
    } else if (!std::isnan(t0)) {
      break;
    }
  }
  return {t0, t1 - 0.5 * window};
}

std::vector<ImuSample> imuBetween(const std::vector<ImuSample>& imu, double t0, double t1) {
  std::vector<ImuSample> out;
  for (const ImuSample& s : imu) {
    if (s.t >= t0 && s.t <= t1) out.push_back(s);
  }
  return out;
}

}  // namespace

Eigen::Matrix<double, 8, 8> priorCalibrationCovariance(const CalibrationPrior& prior) {
  if (prior.covariance) return *prior.covariance;
  Eigen::Matrix<double, 8, 8> P = Eigen::Matrix<double, 8, 8>::Zero();
  P(calib_index::kSv, calib_index::kSv) = prior.sd_s_v * prior.sd_s_v;
  P(calib_index::kSw, calib_index::kSw) = prior.sd_s_w * prior.sd_s_w;
  P.block<3, 3>(calib_index::kP, calib_index::kP) = prior.sd_p_b_m.cwiseAbs2().asDiagonal();
  // Roll/pitch/yaw sigmas mapped into the right-perturbation tangent space.
  const Eigen::Matrix3d Jinv = rpyTangentJacobian(prior.mean.q_b_m).inverse();
  P.block<3, 3>(calib_index::kTheta, calib_index::kTheta) =
      Jinv * Eigen::Matrix3d(prior.sd_rpy_b_m.cwiseAbs2().asDiagonal()) * Jinv.transpose();
  return P;
}

std::optional<InitialState> findInitialState(const CalibrationInputs& in,
                                             const CalibrationOptions& options,
                                             const CalibrationPrior& calib_prior, double t_from,
                                             std::string* why, InitialRtkCache* cache) {
  const DatasetDescription& d = in.description;
  const InitOptions& io = options.init;
  const OdometerCalibration& prior = calib_prior.mean;
  const Eigen::Matrix3d R_b_m = prior.q_b_m.toRotationMatrix();
  const LocalFrame base_frame(in.base_e);
  auto fail = [&](const std::string& reason) -> std::optional<InitialState> {
    if (why) *why = reason;
    return std::nullopt;
  };
  t_from = std::max(t_from, in.imu.front().t);

  // Roll, pitch and gyro bias: from the first static window, else the first second in motion.
  const auto [ts0, ts1] =
      firstStaticRun(in.odom, t_from, io.static_speed, options.models.motion.window_s);
  const bool have_static = !std::isnan(ts0) && ts1 - ts0 >= io.min_static_s && ts0 - t_from < 1.0;
  std::vector<ImuSample> window =
      have_static ? imuBetween(in.imu, ts0, ts1) : imuBetween(in.imu, t_from, t_from + 1.0);
  if (window.size() < 2) return fail("fewer than two IMU samples at the start");
  const ImuNoise& noise = d.imu_noise;
  StaticAlignment align = alignStatic(window, 0.0, base_frame.omega_ie_n(),
                                      noise.gyro_noise_density, noise.accel_noise_density);
  if (!have_static) align.b_g.setZero();
  // The static mean is one measurement of the bias, the turn-on prior another; for a good gyro
  // the prior is the tighter of the two.
  if (have_static) align = withGyroBiasPrior(align, noise.gyro_bias_sigma);
  const double t_anchor_min = have_static ? ts0 : t_from;

  // RTK antenna positions epoch by epoch until the displacement fixes the heading.
  RtkOptions rtk;
  rtk.dd = options.dd;
  rtk.lambda = options.lambda;
  InitialRtkCache local;
  InitialRtkCache& rc = cache ? *cache : local;
  if (!(rc.start == t_anchor_min) || rc.ephemerides != in.nav.ephemerides.size() || !rc.filter) {
    rc.start = t_anchor_min;
    rc.ephemerides = in.nav.ephemerides.size();
    rc.orbits = std::make_unique<BroadcastOrbits>(in.nav);
    rc.filter = std::make_unique<RtkFilter>(*rc.orbits, in.base_e, rtk);
    rc.solutions.clear();
  }
  size_t solved = 0;  // epochs from t_anchor_min on
  std::optional<AntennaFix> anchor;
  bool anchor_static = false;  // the anchor lies in the static window
  BaseEpochMatcher base(in.base.epochs, rtk.max_base_offset);
  size_t k_imu = 0, k_odo = 0;
  // Dead reckoning from the anchor in a yaw-free frame: attitude from the gyro, displacement of
  // the vehicle origin from the odometer through the prior extrinsic and scale.
  Eigen::Matrix3d R0 = rotationFromRpy(Eigen::Vector3d(align.roll, align.pitch, 0.0));
  Eigen::Vector3d d0 = Eigen::Vector3d::Zero();
  double t_dr = 0.0, turned = 0.0;
  Eigen::Matrix3d R0_anchor = R0;
  int good_epochs = 0;
  for (const ObsEpoch& e : in.rover.epochs) {
    if (e.t < t_anchor_min) continue;
    AntennaFix fix;
    if (options.loosely_coupled || options.single_receiver) {
      // The LC scheme starts from the solutions it is given, as it calibrates from them; the
      // single-receiver scheme from its single point positions.
      const PositionFix* p = fixAt(in.positions, e.t, kPositionTolerance);
      if (!p) continue;
      fix = {e.t, p->p_e,
             options.lc.sigma_scale * std::sqrt(0.5 * (p->cov_enu(0, 0) + p->cov_enu(1, 1)))};
    } else {
      const ObsEpoch* base_epoch = base.nearest(e.t);
      if (solved == rc.solutions.size()) rc.solutions.push_back(rc.filter->process(e, base_epoch));
      const RtkSolution sol = rc.solutions[solved++];
      if (sol.quality != 1 && sol.quality != 2) continue;
      const Eigen::Matrix3d cov_n = base_frame.R_e_n().transpose() * sol.cov_e * base_frame.R_e_n();
      fix = {e.t, sol.p_e, std::sqrt(0.5 * (cov_n(0, 0) + cov_n(1, 1))), cov_n};
    }
    ++good_epochs;
    // The anchor is the last good epoch inside the static window (or the first one in motion).
    const bool in_static = have_static && e.t <= ts1;
    if (!anchor || in_static) {
      anchor = fix;
      anchor_static = in_static;
      t_dr = e.t;
      R0 = rotationFromRpy(Eigen::Vector3d(align.roll, align.pitch, 0.0));
      R0_anchor = R0;
      d0.setZero();
      turned = 0.0;
      continue;
    }
    // Dead-reckon from t_dr to e.t.
    while (k_imu + 1 < in.imu.size() && in.imu[k_imu + 1].t <= t_dr) ++k_imu;
    for (size_t k = k_imu; k + 1 < in.imu.size() && in.imu[k].t < e.t; ++k) {
      const double a = std::max(in.imu[k].t, t_dr), c = std::min(in.imu[k + 1].t, e.t);
      if (c <= a) continue;
      const Eigen::Vector3d w = 0.5 * (in.imu[k].gyro + in.imu[k + 1].gyro) - align.b_g;
      // Vehicle-origin velocity from the odometer sample nearest in time.
      while (k_odo + 1 < in.odom.size() &&
             std::abs(in.odom[k_odo + 1].t - a) <= std::abs(in.odom[k_odo].t - a)) {
        ++k_odo;
      }
      const double v = (1.0 + prior.s_v) * in.odom[k_odo].v;
      d0 += R0 * R_b_m * Eigen::Vector3d(0.0, v, 0.0) * (c - a);
      R0 = R0 * expSO3(w * (c - a));
      turned += std::abs(w.dot(R0.transpose().col(2))) * (c - a);
    }
    t_dr = e.t;
    const LocalFrame frame(anchor->p_e);
    const Eigen::Vector3d d_n = frame.enuFromEcef(fix.p_e);  // antenna displacement
    // The same displacement dead-reckoned: vehicle origin plus the change of the lever arm
    // from the vehicle origin to the antenna.
    const Eigen::Vector3d lever = d.p_b_g - prior.p_b_m;
    const Eigen::Vector3d d0_ant = d0 + (R0 - R0_anchor) * lever;
    const double dist = d_n.head<2>().norm();
    const double sd_disp = std::hypot(anchor->sd_h, fix.sd_h);
    const double sd_heading = std::atan2(sd_disp, std::max(dist, 1e-9));
    if (turned > io.max_turn_deg * kDegToRad) {
      // Too much turning for a clean baseline: restart the baseline here.
      anchor = fix;
      anchor_static = false;
      R0_anchor = R0;
      d0.setZero();
      turned = 0.0;
      continue;
    }
    if (dist < io.min_distance || sd_heading > io.max_heading_sigma_deg * kDegToRad) continue;
    if (d0_ant.head<2>().norm() < 0.5 * dist) continue;  // odometer disagrees: keep driving
    const double yaw =
        std::atan2(d_n.y(), d_n.x()) - std::atan2(d0_ant.y(), d0_ant.x());  // n from yaw-free

    InitialState s;
    s.origin_e = anchor->p_e;
    s.heading_baseline_m = dist;
    s.heading_sigma = sd_heading;
    s.static_window_s = have_static ? ts1 - ts0 : 0.0;
    const Eigen::Matrix3d Rz = rotationFromRpy(Eigen::Vector3d(0.0, 0.0, yaw));
    const Eigen::Matrix3d R_n_b = Rz * R0;
    if (have_static) {
      // Again with the heading known, for the Earth rate's share of the gyro mean.
      const Eigen::Matrix3d R_static =
          Rz * rotationFromRpy(Eigen::Vector3d(align.roll, align.pitch, 0.0));
      const double yaw_static = rpyFromRotation(R_static).z();
      align = alignStatic(window, yaw_static, frame.omega_ie_n(), noise.gyro_noise_density,
                          noise.accel_noise_density);
    }
    double v_odo = 0.0;
    if (anchor_static) {
      // Rewind to the last static epoch: the state there is known as well (at rest, the heading
      // now found), and the filter then sees the start of the motion, whose accelerations tell
      // the IMU's heading apart from the extrinsic's.
      const Eigen::Matrix3d R_n_b0 = Rz * R0_anchor;
      s.x.t = anchor->t;
      s.x.q_n_b = Eigen::Quaterniond(R_n_b0).normalized();
      s.x.p_n_b = -R_n_b0 * d.p_b_g;
      s.x.v_n_b.setZero();
    } else {
      s.x.t = e.t;
      s.x.q_n_b = Eigen::Quaterniond(R_n_b).normalized();
      s.x.p_n_b = d_n - R_n_b * d.p_b_g;
      v_odo = (1.0 + prior.s_v) * in.odom[k_odo].v;
      const Eigen::Vector3d w_now = in.imu[std::min(k_imu, in.imu.size() - 1)].gyro - align.b_g;
      s.x.v_n_b = R_n_b * (R_b_m * Eigen::Vector3d(0.0, v_odo, 0.0) + w_now.cross(-prior.p_b_m));
    }
    const AntennaFix& at_state = anchor_static ? *anchor : fix;
    s.x.b_g = have_static ? align.b_g : Eigen::Vector3d::Zero();
    s.x.b_a.setZero();

    // Covariance. The heading error: yaw_b = measured - (extrinsic yaw error seen in n).
    const Eigen::Matrix<double, 8, 8> Pc = priorCalibrationCovariance(calib_prior);
    const Eigen::Matrix3d R_n_bs = s.x.q_n_b.toRotationMatrix();
    const Eigen::Matrix3d R_n_m = R_n_bs * R_b_m;
    const Eigen::RowVector3d ez_m = R_n_m.row(2);            // d(yaw of m)/d theta_b_m
    const Eigen::Vector3d ez_b = R_n_bs.row(2).transpose();  // n's up axis in b
    const Eigen::Matrix3d Ptheta = Pc.block<3, 3>(calib_index::kTheta, calib_index::kTheta);
    const double var_yaw = sd_heading * sd_heading + ez_m * Ptheta * ez_m.transpose();
    const double tilt_sd =
        have_static ? std::max(std::hypot(align.sd_tilt, noise.accel_bias_sigma / 9.8), 1e-3)
                    : io.attitude_sigma_deg * kDegToRad;
    // Attitude tangent (b frame): tilt about n's east and north axes, yaw about up.
    const Eigen::Matrix3d R_b_n = R_n_bs.transpose();
    Eigen::Matrix3d Patt =
        R_b_n * Eigen::Vector3d(tilt_sd * tilt_sd, tilt_sd * tilt_sd, var_yaw).asDiagonal() *
        R_b_n.transpose();
    const double lever_sd = d.p_b_g.norm() * std::sqrt(var_yaw);
    // The single-receiver track's sigma is its shape's; its offset is the single point
    // position's metres.
    const double sd_abs = options.single_receiver
                              ? std::max(at_state.sd_h, options.single.position_sigma_min_m)
                              : at_state.sd_h;
    const double sd_pos = std::hypot(sd_abs, lever_sd) + 0.01;
    // An RTK anchor's own covariance, its height's and its correlations too: a float solution's
    // height sigma is several times its horizontal one. With the horizontal one alone, a first
    // float 1.58 m up (2.3 of its own height sigmas) lay at 6 of the prior's, and the EKF held
    // integers that fit it (GNSS every 30 s; ctest -R SparseGnss). The LC and single-receiver
    // schemes keep the horizontal sigma on all three axes, as before: their own solutions' heights,
    // not RTK's.
    const Eigen::Matrix3d P_pos =
        options.single_receiver || options.loosely_coupled
            ? Eigen::Matrix3d(Eigen::Matrix3d::Identity() * sd_pos * sd_pos)
            : Eigen::Matrix3d(at_state.cov_n +
                              Eigen::Matrix3d::Identity() * (lever_sd * lever_sd + 1e-4));
    const double sd_vel = anchor_static ? options.models.zupt_sigma
                                        : io.velocity_sigma + std::abs(v_odo) * std::sqrt(var_yaw);
    const Eigen::Vector3d sd_bg =
        have_static ? Eigen::Vector3d(align.sd_b_g.cwiseMax(1e-7))
                    : Eigen::Vector3d(Eigen::Vector3d::Constant(noise.gyro_bias_sigma));
    auto& P = s.P_nav;
    P.block<3, 3>(0, 0) = P_pos;
    P.block<3, 3>(3, 3) = Patt;
    P.block<3, 3>(6, 6) = Eigen::Matrix3d::Identity() * sd_vel * sd_vel;
    P.block<3, 3>(9, 9) = Eigen::Matrix3d::Identity() * std::pow(noise.accel_bias_sigma, 2);
    P.block<3, 3>(12, 12) = sd_bg.cwiseAbs2().asDiagonal();
    // Cross-covariance of the attitude with the calibration: the heading is the displacement's
    // minus the extrinsic yaw, so cov(ez_b yaw, c) = -ez_b ez_m P_theta,c for every calibration
    // state c the extrinsic rotation is correlated with (a prior carried over from an earlier
    // run is fully correlated; setting the theta block alone left the joint P indefinite).
    s.P_nav_calib.block<3, 8>(3, 0) = -ez_b * (ez_m * Pc.block<3, 8>(calib_index::kTheta, 0));
    return s;
  }
  if (good_epochs == 0) {
    return fail(options.single_receiver ? "no single point position at a GNSS epoch (check the "
                                          "navigation data)"
                : options.loosely_coupled
                    ? "no position solution at a GNSS epoch"
                    : "no RTK solution of the antenna (check base position and nav)");
  }
  return fail("the robot never drove far enough in a straight enough line (at least " +
              fixedText(io.min_distance, 1) + " m, turning less than " +
              fixedText(io.max_turn_deg, 0) +
              " deg) for the GNSS displacement to give the heading within " +
              fixedText(io.max_heading_sigma_deg, 1) +
              " deg (calibration.init.min_distance, max_turn_deg, max_heading_sigma_deg)");
}

}  // namespace giocal
