// The factor graph's odometer intervals: the factor of one interval, and the check of its samples
// against the IMU between the solved states at both ends, which leaves out samples of wheel slip.
#include <algorithm>
#include <cmath>

#include "common/gnss/spp.h"
#include "common/imu/gyro_mean.h"
#include "common/imu/imu_preintegration.h"
#include "common/math/median.h"
#include "common/math/rotation.h"
#include "common/models/odometer_preintegration_model.h"
#include "common/models/planar_motion_projection.h"
#include "common/models/standstill_projection.h"
#include "common/odometer/odometer_preintegration.h"
#include "common/odometer/vehicle_velocity.h"
#include "fgo/factor_graph_core.h"
#include "fgo/factor_tag.h"
#include "fgo/predicted_residual.h"

namespace giocal {

using fgo_tag::tagged;
using state::kPbm, state::kQbm;

namespace {
constexpr double kRateHalfWindow = 0.25;  // the lever arm's rate: a mean over 0.5 s [s]
}  // namespace

std::vector<OdomSample> FactorGraphCore::odometerSamples(double t0, double t1) const {
  const auto after = [&](double t) {
    return std::upper_bound(in_.odom.begin(), in_.odom.end(), t,
                            [](double x, const OdomSample& s) { return x < s.t; });
  };
  const auto first = after(t0);
  const auto last = after(t1);
  return {first == in_.odom.begin() ? first : std::prev(first),
          last == in_.odom.end() ? last : std::next(last)};
}

std::vector<OdomSample> FactorGraphCore::intervalSamples(const FgoEpoch& prev,
                                                         const FgoEpoch& e) const {
  if (in_.odom.empty() || in_.odom.front().t > prev.t) return {};
  std::vector<OdomSample> samples = odometerSamples(prev.t, e.t);
  if (longestOdometerGap(samples, prev.t, e.t) > o_.max_odometer_gap_s) return {};
  return samples;
}

void FactorGraphCore::addOdometerFactor(const FgoEpoch& prev, const FgoEpoch& e,
                                        const std::vector<OdomSample>& samples) {
  const NavState x_prev = nav(prev);
  auto odo = std::make_shared<OdometerPreintegration>(
      odometerPreintegrationNoise(in_.description.odom_noise,
                                  in_.description.imu_noise.gyro_noise_density, o_.models),
      w_.value(prev.sv)[0], w_.value(prev.sw)[0]);
  odo->integrateSamples(samples, prev.t, e.t);
  // With the odometer's delay as a state: the IMU's velocity and rate at both ends.
  std::optional<PoseRates> rates;
  std::vector<StateKey> vars{prev.p, prev.q, e.p, e.q, prev.sv, prev.sw, kPbm, kQbm};
  if (o_.estimate_odometer_delay) {
    const double density = in_.description.imu_noise.gyro_noise_density;
    rates = PoseRates{x_prev.v_n_b, poseRate(in_.imu, prev.t, x_prev.b_g, density), w_.value(e.v),
                      poseRate(in_.imu, e.t, x_prev.b_g, density)};
    vars.push_back(state::kTdOdo);
  }
  std::shared_ptr<const MeasurementModel> model =
      planar(std::make_shared<OdometerPreintegrationModel>(
          odo, !in_.description.odom_noise.measures_yaw_rate, rates));
  if (e.still && prev.still) model = std::make_shared<StandstillProjection>(model);
  w_.addFactor({model, vars, 0.0, tagged("odometer", e.k)});
}

bool FactorGraphCore::leaveOutSlips(const FgoEpoch& prev, const FgoEpoch& e) {
  if (!(fo_.odometer_slip_sigma > 0.0) || (prev.still && e.still)) return false;
  const std::vector<OdomSample> samples = intervalSamples(prev, e);
  if (samples.empty()) return false;  // no interval factor at this epoch
  // The IMU's velocity from the solved state before, pinned to the solved state after: over a
  // second a MEMS gyro's attitude walk alone moves the prediction by centimetres per second
  // (paper preset, 3 cm/s), a slip at 0.25 m/s by 7.5 cm/s.
  const NavState x0 = nav(prev), x1 = nav(e);
  ImuPreintegration along(in_.description.imu_noise, frame_.gravity_n(x0.p_n_b),
                          frame_.omega_ie_n(), x0.b_a, x0.b_g, gyroTilt());
  std::vector<NavState> x;     // the prediction at each sample in (prev.t, e.t]
  std::vector<size_t> inside;  // those samples' indices
  double integrated_to = prev.t;
  for (size_t k = 0; k < samples.size(); ++k) {
    if (samples[k].t <= prev.t || samples[k].t > e.t) continue;
    along.integrateSamples(in_.imu, integrated_to, samples[k].t);
    integrated_to = samples[k].t;
    x.push_back(along.predict(x0));
    inside.push_back(k);
  }
  if (x.empty()) return false;
  if (e.t > integrated_to) along.integrateSamples(in_.imu, integrated_to, e.t);
  const Eigen::Vector3d v_miss = x1.v_n_b - along.predict(x0).v_n_b;
  const SlidingWindow& window = w_;  // reading only: keeps the factorization cached
  const Eigen::Vector3d p_b_m = window.value(kPbm);
  const Eigen::Quaterniond q_b_m = quatFromWxyz(window.value(kQbm).data());
  std::vector<double> r;
  for (size_t j = 0; j < x.size(); ++j) {
    const OdomSample& s = samples[inside[j]];
    const Eigen::Vector3d v_n = x[j].v_n_b + (s.t - prev.t) / (e.t - prev.t) * v_miss;
    const GyroMean rate =
        meanGyro(in_.imu, s.t, kRateHalfWindow, in_.description.imu_noise.gyro_noise_density);
    r.push_back(s.v - vehicleVelocity(v_n, x[j].q_n_b, rate.rate, x[j].b_g, p_b_m, q_b_m).v_m.y());
  }
  // Calibration errors move the interval's samples together; a slip moves some of them.
  const double m = median(r);
  const double gate = fo_.odometer_slip_sigma * in_.description.odom_noise.speed_sigma;
  std::vector<bool> slipped(samples.size(), false);
  long n = 0;
  for (size_t j = 0; j < r.size(); ++j) {
    if (std::abs(r[j] - m) <= gate) continue;
    slipped[inside[j]] = true;
    ++n;
  }
  if (n == 0) return false;
  std::vector<OdomSample> kept;
  for (size_t k = 0; k < samples.size(); ++k) {
    if (!slipped[k]) kept.push_back(samples[k]);
  }
  run_->count(Counter::kOdometerSlips, n);
  w_.removeFactors(tagged("odometer", e.k));
  addOdometerFactor(prev, e, kept);
  return true;
}

bool FactorGraphCore::rejectOdometer(const FgoEpoch& e) {
  // As the EKF's gate of an odometer interval: an interval the rest of the window cannot fit
  // (wheel slip) leaves the window instead of pulling the scales. The solved residual alone
  // understates it by what the interval pulled the solution (predicted_residual.h).
  const std::string tag = tagged("odometer", e.k);
  const SlidingWindow& window = w_;  // reading only: keeps the factorization cached
  for (const Factor& f : window.factors()) {
    if (f.tag != tag) continue;
    const PredictedResidual p = predictedResidual(window, f);
    if (p.dof == 0 || p.chi2 <= chi2Quantile(o_.chi2_probability, p.dof)) return false;
    run_->count(Counter::kOdometerRejected);
    w_.removeFactors(tag);
    return true;
  }
  return false;
}

}  // namespace giocal
