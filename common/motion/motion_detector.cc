#include "common/motion/motion_detector.h"

#include <algorithm>
#include <cmath>

namespace giocal {

template <typename T>
void MotionDetector::Window<T>::add(double t, const T& value, double length) {
  // A sample older than the last one restarts the window rather than corrupting the mean.
  if (!samples.empty() && t <= samples.back().first) {
    samples.clear();
    sum = sum - sum;
  }
  samples.push_back({t, value});
  sum += value;
  while (!samples.empty() && samples.front().first < t - length) {
    sum -= samples.front().second;
    samples.pop_front();
  }
}

template <typename T>
bool MotionDetector::Window<T>::full(double length) const {
  // Covered when the samples span at least 90 % of the window (sampling jitter and the edges).
  return samples.size() >= 2 && samples.back().first - samples.front().first >= 0.9 * length;
}

void MotionDetector::addImu(double t, const Eigen::Vector3d& gyro,
                            const Eigen::Vector3d& specific_force) {
  gyro_.add(t, gyro, options_.window_s);
  force_.add(t, specific_force, options_.window_s);
  recent_force_.add(t, specific_force, recentLength());
}

void MotionDetector::addOdometer(double t, double forward_speed) {
  speed_.add(t, forward_speed, options_.window_s);
}

double MotionDetector::meanGyroNorm() const { return gyro_.mean().norm(); }
double MotionDetector::meanSpeed() const { return speed_.mean(); }

double MotionDetector::staticGyroThreshold() const {
  return std::max(options_.zupt_max_gyro,
                  4.0 * options_.gyro_noise_density / std::sqrt(options_.window_s));
}

bool MotionDetector::accelSteady() const {
  // The recent mean is a subset of the window's: their difference has variance
  // density^2 (1/recent - 1/window) per axis.
  const double sd = options_.accel_noise_density *
                    std::sqrt(std::max(0.0, 1.0 / recentLength() - 1.0 / options_.window_s));
  const double threshold = std::max(options_.zupt_max_accel_change, 5.0 * sd);
  return (recent_force_.mean() - force_.mean()).norm() < threshold;
}

bool MotionDetector::isStatic() const {
  const bool wheels_still =
      speed_.samples.empty() || std::abs(speed_.mean()) < options_.zupt_max_speed;
  return gyro_.full(options_.window_s) && meanGyroNorm() < staticGyroThreshold() && accelSteady() &&
         wheels_still;
}

bool MotionDetector::nhcApplies() const {
  return gyro_.full(options_.window_s) && speed_.full(options_.window_s) &&
         meanGyroNorm() < options_.nhc_max_gyro && speed_.mean() > options_.nhc_min_speed;
}

}  // namespace giocal
