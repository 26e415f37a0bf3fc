// MotionDetector: decides from the last second of IMU and odometer data whether the robot stands
// still (ZUPT) or drives straight fast enough for the non-holonomic constraint (NHC).
//
// Why the accelerometer too (not in the paper's thresholds): a mean over the last second of
// wheel speed and gyro stays under its threshold for the first few tenths of a second of a
// straight start (longer with late wheel stamps), and a ZUPT at every sample of them holds the
// velocity at zero while the robot already moves. That lag read as an odometer that is early
// (the EKF's delay 2-4 ms low on the field preset, docs/results.md). The specific force's mean
// over the last fifth of the window leaves the window's mean as soon as the robot accelerates.
#pragma once

#include <Eigen/Core>
#include <utility>

#include "common/containers/ring_queue.h"

namespace giocal {

/// Thresholds of the reference paper, configurable.
struct MotionDetectorOptions {
  double window_s = 1.0;                               // averaging window [s]
  double zupt_max_gyro = 0.05 * 0.017453292519943295;  // |mean w| below this is static [rad/s]
  double zupt_max_speed = 0.01;  // |mean odometer speed| below this is static, if any [m/s]
  double nhc_max_gyro = 5.0 * 0.017453292519943295;  // |mean w| below this: not turning [rad/s]
  double nhc_min_speed = 1.0;                        // mean forward speed above this for NHC [m/s]
  /// The gyro's white noise [rad/s/sqrt(Hz)]: a mean over the window cannot be told from zero
  /// below 4 density / sqrt(window), so the static threshold is at least that (0: paper's alone).
  double gyro_noise_density = 0.0;
  /// |mean specific force over the last fifth of the window - that over the window| below this
  /// is static [m/s^2]; at least 5 accelerometer noise densities' worth of that difference.
  double zupt_max_accel_change = 0.01;
  double accel_noise_density = 0.0;  // the accelerometer's white noise [m/s^2/sqrt(Hz)]
};

/// The detector's thresholds with the noise of the IMU in use.
inline MotionDetectorOptions withImuNoise(MotionDetectorOptions o, double gyro_noise_density,
                                          double accel_noise_density) {
  o.gyro_noise_density = gyro_noise_density;
  o.accel_noise_density = accel_noise_density;
  return o;
}

class MotionDetector {
 public:
  explicit MotionDetector(const MotionDetectorOptions& options = {}) : options_(options) {}

  /// gyro should be bias-compensated: a MEMS bias (hundreds of deg/h) exceeds the ZUPT threshold;
  /// the specific force need not be (only its changes are used).
  void addImu(double t, const Eigen::Vector3d& gyro, const Eigen::Vector3d& specific_force);
  void addOdometer(double t, double forward_speed);

  /// |mean gyro| below the static threshold over a full window ending at the latest sample, the
  /// specific force steady (accelSteady), and the wheels still (|mean speed| below
  /// zupt_max_speed) when odometer samples are present.
  bool isStatic() const;
  /// |mean gyro| below nhc_max_gyro and mean odometer speed above nhc_min_speed over full windows.
  bool nhcApplies() const;
  /// The static threshold in use [rad/s].
  double staticGyroThreshold() const;
  /// The mean specific force of the window's last fifth within the accelerometer threshold of
  /// the window's mean.
  bool accelSteady() const;

  double meanGyroNorm() const;  // |mean gyro| over the window [rad/s]
  double meanSpeed() const;

 private:
  template <typename T>
  struct Window {
    RingQueue<std::pair<double, T>> samples;  // (t, value)
    T sum{};
    void add(double t, const T& value, double length);
    bool full(double length) const;
    T mean() const { return samples.empty() ? T{} : T(sum / static_cast<double>(samples.size())); }
  };
  MotionDetectorOptions options_;
  double recentLength() const { return 0.2 * options_.window_s; }
  Window<Eigen::Vector3d> gyro_{{}, Eigen::Vector3d::Zero()};
  Window<Eigen::Vector3d> force_{{}, Eigen::Vector3d::Zero()};
  Window<Eigen::Vector3d> recent_force_{{}, Eigen::Vector3d::Zero()};
  Window<double> speed_{{}, 0.0};
};

}  // namespace giocal
