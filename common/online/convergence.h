// ConvergenceMonitor: decides, estimate by estimate, when each calibration parameter has converged
// (its sigma below a target and its value steady over a time) and when the calibration is done.
#pragma once

#include <array>
#include <deque>
#include <string>
#include <vector>

#include "common/calibration/calibration_run.h"

namespace giocal {

struct ConvergenceOptions {
  double sigma_scale = 2e-3;          // target 1-sigma of s_v and s_w
  double sigma_lever_m = 0.05;        // of p_b_m.x and p_b_m.y [m]
  double sigma_roll_pitch_deg = 0.5;  // of roll and pitch of q_b_m [deg]
  double sigma_yaw_deg = 1.0;         // of yaw of q_b_m [deg]
  // The value must stay within its target over this long (data time) [s].
  double steady_s = 30.0;
};

/// A parameter's convergence, or its leaving it again (the estimator re-opened its covariance).
struct ConvergenceEvent {
  int state = 0;  // calibration.csv order (common/calibration/weak_directions.h)
  bool converged = true;
  double t = 0.0, value = 0.0, sigma = 0.0;  // value and sigma in calibration.csv units
};

class ConvergenceMonitor {
 public:
  /// `holds_z`: p_b_m.z is held (unobservable), so it is left out of "done".
  /// `held`: the states (calibration.csv order) the run does not calibrate: p_b_m.z held, s_w
  /// of a speed-only odometer.
  ConvergenceMonitor(const ConvergenceOptions& options, std::vector<int> held);

  /// The events this estimate causes.
  std::vector<ConvergenceEvent> update(const CalibrationEstimate& e);
  bool converged(int state) const { return converged_[static_cast<size_t>(state)]; }
  double convergedAt(int state) const { return at_[static_cast<size_t>(state)]; }
  /// Every parameter taking part has converged.
  bool done() const;
  bool takesPart(int state) const;
  const std::vector<int>& held() const { return held_; }
  double target(int state) const;

 private:
  ConvergenceOptions o_;
  std::vector<int> held_;
  std::array<std::deque<std::pair<double, double>>, 8> recent_;  // (t, value) over steady_s
  std::array<bool, 8> converged_{};
  std::array<double, 8> at_{};
};

}  // namespace giocal
