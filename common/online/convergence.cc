#include "common/online/convergence.h"

#include <algorithm>
#include <cmath>

#include "common/math/rotation.h"

namespace giocal {

ConvergenceMonitor::ConvergenceMonitor(const ConvergenceOptions& options, std::vector<int> held)
    : o_(options), held_(std::move(held)) {
  at_.fill(NAN);
}

bool ConvergenceMonitor::takesPart(int state) const {
  return std::find(held_.begin(), held_.end(), state) == held_.end();
}

double ConvergenceMonitor::target(int state) const {
  switch (state) {
    case 0:
    case 1:
      return o_.sigma_scale;
    case 5:
    case 6:
      return o_.sigma_roll_pitch_deg;
    case 7:
      return o_.sigma_yaw_deg;
    default:
      return o_.sigma_lever_m;
  }
}

std::vector<ConvergenceEvent> ConvergenceMonitor::update(const CalibrationEstimate& e) {
  const Eigen::Matrix<double, 8, 1> sd = e.sigma();
  const Eigen::Vector3d rpy = rpyFromRotation(e.calib.q_b_m.toRotationMatrix()) * kRadToDeg;
  const double value[8] = {e.calib.s_v,       e.calib.s_w, e.calib.p_b_m.x(), e.calib.p_b_m.y(),
                           e.calib.p_b_m.z(), rpy.x(),     rpy.y(),           rpy.z()};
  std::vector<ConvergenceEvent> events;
  for (int k = 0; k < 8; ++k) {
    if (!takesPart(k)) continue;
    auto& recent = recent_[static_cast<size_t>(k)];
    recent.push_back({e.t, value[k]});
    while (recent.size() > 1 && recent[1].first <= e.t - o_.steady_s) recent.pop_front();
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& [t, v] : recent) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    const bool spans = e.t - recent.front().first >= o_.steady_s;
    const bool now = sd[k] <= target(k) && spans && hi - lo <= target(k);
    bool& was = converged_[static_cast<size_t>(k)];
    // Once converged, only a sigma grown past its target (a re-opened covariance) undoes it.
    const bool lost = was && sd[k] > target(k);
    if ((!was && now) || lost) {
      was = !lost;
      if (was) at_[static_cast<size_t>(k)] = e.t;
      events.push_back({k, was, e.t, value[k], sd[k]});
    }
  }
  return events;
}

bool ConvergenceMonitor::done() const {
  for (int k = 0; k < 8; ++k) {
    if (takesPart(k) && !converged_[static_cast<size_t>(k)]) return false;
  }
  return true;
}

}  // namespace giocal
