// MotionDetector: decides from the last second of IMU and odometer data whether the robot stands
// still (ZUPT) or drives straight fast enough for the non-holonomic constraint (NHC).
#pragma once

#include <Eigen/Core>
#include <deque>

namespace giocal {

/// Thresholds of the reference paper, configurable.
struct MotionDetectorOptions {
  double window_s = 1.0;                               // averaging window [s]
  double zupt_max_gyro = 0.05 * 0.017453292519943295;  // mean |w| below this is static [rad/s]
  double nhc_max_gyro = 5.0 * 0.017453292519943295;    // mean |w| below this is not turning [rad/s]
  double nhc_min_speed = 1.0;  // mean forward speed above this for NHC [m/s]
};

class MotionDetector {
 public:
  explicit MotionDetector(const MotionDetectorOptions& options = {}) : options_(options) {}

  /// gyro should be bias-compensated: a MEMS bias (hundreds of deg/h) exceeds the ZUPT threshold.
  void addImu(double t, const Eigen::Vector3d& gyro);
  void addOdometer(double t, double forward_speed);

  /// Mean |gyro| below zupt_max_gyro over a full window ending at the latest sample.
  bool isStatic() const;
  /// Mean |gyro| below nhc_max_gyro and mean odometer speed above nhc_min_speed over full windows.
  bool nhcApplies() const;

  double meanGyroNorm() const;
  double meanSpeed() const;

 private:
  struct Window {
    std::deque<std::pair<double, double>> samples;  // (t, value)
    double sum = 0.0;
    void add(double t, double value, double length);
    bool full(double length) const;
    double mean() const {
      return samples.empty() ? 0.0 : sum / static_cast<double>(samples.size());
    }
  };
  MotionDetectorOptions options_;
  Window gyro_, speed_;
};

}  // namespace giocal
