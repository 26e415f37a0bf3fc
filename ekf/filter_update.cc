// CalibrationFilter's gated Kalman updates: a model linearized at the current state into rows
// kept from one update to the next, the iterated update, and the held (consider) states.
#include <array>
#include <cmath>

#include "common/calibration/weak_directions.h"
#include "common/math/kalman_update.h"
#include "ekf/calibration_filter.h"

namespace giocal {

const std::vector<int>& CalibrationFilter::heldIndices() {
  const std::array<int, 8> idx = calibrationIndices(s_);
  held_.clear();
  if (options_.hold_calibration) {
    held_.assign(idx.begin(), idx.end());
    if (s_.has(state::kTdOdo)) held_.push_back(s_.offset(state::kTdOdo));
    if (s_.has(state::kGyroTilt)) {
      for (int k = 0; k < 2; ++k) held_.push_back(s_.offset(state::kGyroTilt) + k);
    }
    return held_;
  }
  // States the run keeps at the prior (the vertical lever arm in planar motion, a speed-only
  // odometer's s_w).
  for (int k : held_states_) held_.push_back(idx[static_cast<size_t>(k)]);
  return held_;
}

namespace {

/// A raw gyro sample's white noise, which reaches the residual through H's b_g columns:
/// R += variance H_bg H_bg^T.
void addGyroNoise(MeasurementRows& rows, int bg, double variance) {
  if (!(variance > 0.0)) return;
  if (rows.H.rows() <= 6) {
    // A vehicle-motion model's few rows: the same product off the heap.
    using Rows3 = Eigen::Matrix<double, Eigen::Dynamic, 3, 0, 6, 3>;
    const Rows3 H_bg = rows.H.middleCols(bg, 3);
    rows.R += variance * H_bg * H_bg.transpose();
  } else {
    const Eigen::MatrixXd H_bg = rows.H.middleCols(bg, 3);
    rows.R += variance * H_bg * H_bg.transpose();
  }
}

/// What an update did; its correction is applied to the state, not returned (dx is empty, so
/// returning it allocates nothing).
UpdateResult outcome(const UpdateResult& r) {
  return {Eigen::VectorXd(), r.nis, r.accepted, r.numerical_failure};
}

}  // namespace

MeasurementRows CalibrationFilter::rows(const MeasurementModel& model,
                                        const std::vector<StateKey>& keys,
                                        double gyro_variance) const {
  MeasurementRows rows = linearize(model, s_.bind(keys), s_.dim());
  addGyroNoise(rows, s_.offset(state::kBg), gyro_variance);
  return rows;
}

MeasurementRows& CalibrationFilter::linearizeRows(const MeasurementModel& model,
                                                  const std::vector<StateKey>& keys,
                                                  double gyro_variance) {
  s_.bind(keys, bindings_);
  LinearizationCache::Storage& kept = linearization_.forModel(model);
  linearize(model, bindings_, s_.dim(), kept.rows, kept.scratch);
  addGyroNoise(kept.rows, s_.offset(state::kBg), gyro_variance);
  return kept.rows;
}

UpdateResult CalibrationFilter::update(const MeasurementModel& model,
                                       const std::vector<StateKey>& keys, double chi2_gate,
                                       double gyro_variance, int iterations) {
  if (iterations <= 1)
    return updateLinearized(linearizeRows(model, keys, gyro_variance), chi2_gate);
  // Iterated EKF (Gauss-Newton on the prior and the measurement): relinearize at the updated
  // state, keep the prior covariance; the last iteration's gain updates the covariance. The
  // covariance is left as the prior's until then: an earlier iteration gives its correction
  // only (its downdate, and the copy that undid it, were 4.5 M of the 32 M these updates cost
  // on paper seed 1, callgrind).
  // Assigned, not constructed: the copy reuses the storage of the last update's (a registry
  // constructed here allocated once per variable, about 55 times per odometer interval).
  iterate_prior_ = s_;
  const StateRegistry& prior = iterate_prior_;
  UpdateResult& r = result_;
  for (int it = 0; it < iterations; ++it) {
    MeasurementRows& lin = linearizeRows(model, keys, gyro_variance);
    s_.minus(prior, delta_);
    h_delta_.noalias() = lin.H * delta_;
    lin.residual -= h_delta_;  // residual linearized about the prior: r(x_i) - H d_i
    s_.setValues(prior);       // values back to the prior's (whole-registry copies cost more)
    kalmanGainInto(s_.covariance(), lin, it == 0 ? chi2_gate : INFINITY, heldIndices(), workspace_,
                   r);
    numerical_failures_ += r.numerical_failure;
    if (!r.accepted) return outcome(r);  // s_ holds the prior again
    const bool last = it + 1 == iterations || (r.dx - delta_).norm() < 1e-9;
    if (last) {
      kalmanDowndate(s_.covariance(), heldIndices(), workspace_, r);
      numerical_failures_ += r.numerical_failure;
      if (!r.accepted) return outcome(r);  // the covariance is restored, s_ holds the prior
    }
    s_.correct(r.dx);
    if (last) break;
  }
  return outcome(r);
}

UpdateResult CalibrationFilter::updateLinearized(const MeasurementRows& rows, double chi2_gate) {
  kalmanUpdateInto(s_.covariance(), rows, chi2_gate, heldIndices(), workspace_, result_);
  numerical_failures_ += result_.numerical_failure;
  if (result_.accepted) s_.correct(result_.dx);
  return outcome(result_);
}

}  // namespace giocal
