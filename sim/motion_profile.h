// MotionProfile: forward speed V(t) and yaw rate W(t) of a differential-drive vehicle built from
// segments (stationary, speed change, straight, arc, turn in place, figure eight), joined by
// quintic smooth steps so speed, yaw rate and their first two derivatives are continuous.
#pragma once

#include <string>
#include <vector>

namespace giocal::sim {

struct SegmentSpec {
  std::string type;       // stationary | speed | straight | arc | turn_in_place | figure_eight
  double duration = 0.0;  // [s]; arc and turn_in_place may give angle_deg instead
  double speed = -1.0;    // target speed [m/s] (speed segments; others keep the current one)
  double radius = 0.0;    // arc / figure_eight radius [m]
  std::string direction = "left";  // arc turning direction (left = counter-clockwise)
  double angle_deg = 0.0;          // arc / turn_in_place angle; 0 means "use duration"
  double rate_deg_s = 0.0;         // turn_in_place yaw rate
  double transition = 1.0;         // smooth-step length at the segment start [s]
};

class MotionProfile {
 public:
  /// Expands the segments (a figure eight becomes two opposite full circles).
  explicit MotionProfile(const std::vector<SegmentSpec>& segments);

  double duration() const { return phases_.empty() ? 0.0 : phases_.back().t_end; }
  /// Forward speed and its first two derivatives at t.
  void speed(double t, double& v, double& v_dot) const;
  /// Yaw rate and its derivative at t.
  void yawRate(double t, double& w, double& w_dot) const;

 private:
  struct Phase {
    double t_start, t_end, transition;
    double v_from, v_to, w_from, w_to;
  };
  const Phase& phaseAt(double t) const;
  std::vector<Phase> phases_;
};

}  // namespace giocal::sim
