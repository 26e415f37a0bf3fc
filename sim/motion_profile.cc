#include "sim/motion_profile.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/math/rotation.h"

namespace giocal::sim {

namespace {

// Quintic smooth step on [0, 1] and its derivative with respect to u.
double smooth(double u) { return u * u * u * (10.0 + u * (-15.0 + 6.0 * u)); }
double smoothDot(double u) { return 30.0 * u * u * (1.0 - u) * (1.0 - u); }

void blend(double t, double t0, double tau, double from, double to, double& x, double& x_dot) {
  if (tau <= 0.0 || t >= t0 + tau) {
    x = to;
    x_dot = 0.0;
    return;
  }
  const double u = std::clamp((t - t0) / tau, 0.0, 1.0);
  x = from + (to - from) * smooth(u);
  x_dot = (to - from) * smoothDot(u) / tau;
}

}  // namespace

MotionProfile::MotionProfile(const std::vector<SegmentSpec>& segments) {
  double t = 0.0, v = 0.0, w = 0.0;
  auto add = [&](double duration, double transition, double v_to, double w_to) {
    if (!(duration > 0.0)) throw std::invalid_argument("motion segment needs a positive duration");
    phases_.push_back({t, t + duration, std::min(transition, duration), v, v_to, w, w_to});
    t += duration;
    v = v_to;
    w = w_to;
  };
  for (const SegmentSpec& s : segments) {
    const double tr = s.transition;
    if (s.type == "stationary") {
      add(s.duration, tr, 0.0, 0.0);
    } else if (s.type == "speed") {
      if (s.speed < 0.0) throw std::invalid_argument("speed segment needs 'speed' >= 0");
      add(s.duration, s.duration, s.speed, 0.0);  // the whole segment is the ramp
    } else if (s.type == "straight") {
      add(s.duration, tr, s.speed >= 0.0 ? s.speed : v, 0.0);
    } else if (s.type == "arc" || s.type == "figure_eight") {
      const double speed = s.speed >= 0.0 ? s.speed : v;
      if (!(s.radius > 0.0) || !(speed > 0.0)) {
        throw std::invalid_argument(s.type + " needs radius > 0 and a speed > 0");
      }
      const double rate = speed / s.radius;
      if (s.type == "figure_eight") {
        // Two full circles in opposite directions; the ramp of each adds half its length.
        const double d = 2.0 * M_PI / rate + tr / 2.0;
        add(d, tr, speed, rate);
        add(d, tr, speed, -rate);
      } else {
        const double sign = s.direction == "right" ? -1.0 : 1.0;
        if (s.direction != "left" && s.direction != "right") {
          throw std::invalid_argument("arc direction must be left or right");
        }
        const double d = s.angle_deg > 0.0 ? s.angle_deg * kDegToRad / rate + tr / 2.0 : s.duration;
        add(d, tr, speed, sign * rate);
      }
    } else if (s.type == "turn_in_place") {
      const double rate = s.rate_deg_s * kDegToRad;
      if (rate == 0.0) throw std::invalid_argument("turn_in_place needs rate_deg_s != 0");
      const double d =
          s.angle_deg > 0.0 ? s.angle_deg * kDegToRad / std::abs(rate) + tr / 2.0 : s.duration;
      add(d, tr, 0.0, rate);
    } else {
      throw std::invalid_argument("unknown motion segment type '" + s.type + "'");
    }
  }
}

const MotionProfile::Phase& MotionProfile::phaseAt(double t) const {
  if (phases_.empty()) throw std::logic_error("empty motion profile");
  auto it = std::upper_bound(phases_.begin(), phases_.end(), t,
                             [](double x, const Phase& p) { return x < p.t_end; });
  return it == phases_.end() ? phases_.back() : *it;
}

void MotionProfile::speed(double t, double& v, double& v_dot) const {
  const Phase& p = phaseAt(t);
  blend(t, p.t_start, p.transition, p.v_from, p.v_to, v, v_dot);
}

void MotionProfile::yawRate(double t, double& w, double& w_dot) const {
  const Phase& p = phaseAt(t);
  blend(t, p.t_start, p.transition, p.w_from, p.w_to, w, w_dot);
}

}  // namespace giocal::sim
