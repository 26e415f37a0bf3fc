// CalibrationFilter's navigation read-out and reset: the state now, the trajectory predicted
// between updates, and moving the pose to a reference (dead reckoning's start).
#include <algorithm>
#include <iterator>

#include "common/math/rotation.h"
#include "ekf/calibration_filter.h"
#include "ekf/imu_propagation.h"

namespace giocal {

NavState CalibrationFilter::nav() const {
  NavState x = navState(s_);
  x.t = t_;
  return x;
}

TruthSample CalibrationFilter::trajectorySample(double t) {
  NavState x = nav();
  t = std::min(t, imu_.back().t);
  if (t > t_) {
    // A row leaves the filter as it was: the whole IMU intervals up to t go into the pending
    // preintegration (the mean only; each sample is integrated once, and the covariance steps
    // close where they would without rows), the piece of the last one up to t into a copy.
    // Closing a step at every row, or cutting an interval there, moved the calibration at
    // rounding level with the output rate.
    const auto after = std::upper_bound(imu_.begin(), imu_.end(), t,
                                        [](double v, const ImuSample& s) { return v < s.t; });
    const double t_whole = std::prev(after)->t;  // imu_.front().t <= t_ < t
    const ImuPreintegration& pre = pendingTo(std::max(t_whole, t_), false);
    if (t > pending_t_) {
      ImuPreintegration piece = pre;
      piece.meanOnly();
      piece.addSamples(imu_, pending_t_, t);
      x = piece.predict(x);
    } else {
      x = pre.predict(x);
    }
  } else {
    t = t_;
  }
  return truthRow(frame_, x, t);
}

void CalibrationFilter::movePose(const Eigen::Vector3d& p_n_b, const Eigen::Vector3d& v_n_b,
                                 const Eigen::Quaterniond& q_n_b) {
  NavState x = navState(s_);
  const Mat3 dR = q_n_b.toRotationMatrix() * x.q_n_b.toRotationMatrix().transpose();
  const auto rotate = [&](const StateKey& key) {
    const Quat q = quatFromWxyz(s_.value(key).data());
    quatToWxyz(Quat(dR * q.toRotationMatrix()).normalized(), s_.value(key).data());
  };
  for (const auto& [p, q] : {std::pair{kOdoP, kOdoQ}, std::pair{kGnssP, kGnssQ}}) {
    if (!s_.has(p)) continue;
    s_.value(p) = p_n_b + dR * (s_.value(p) - x.p_n_b);
    rotate(q);
  }
  if (s_.has(kHeadingClone)) rotate(kHeadingClone);
  x.p_n_b = p_n_b;
  x.v_n_b = v_n_b;
  x.q_n_b = q_n_b;
  setNavState(s_, x);
  pending_.reset();
}

}  // namespace giocal
