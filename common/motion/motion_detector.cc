#include "common/motion/motion_detector.h"

namespace giocal {

void MotionDetector::Window::add(double t, double value, double length) {
  // A sample older than the last one restarts the window rather than corrupting the mean.
  if (!samples.empty() && t <= samples.back().first) {
    samples.clear();
    sum = 0.0;
  }
  samples.emplace_back(t, value);
  sum += value;
  while (!samples.empty() && samples.front().first < t - length) {
    sum -= samples.front().second;
    samples.pop_front();
  }
}

bool MotionDetector::Window::full(double length) const {
  // Covered when the samples span at least 90 % of the window (sampling jitter and the edges).
  return samples.size() >= 2 && samples.back().first - samples.front().first >= 0.9 * length;
}

void MotionDetector::addImu(double t, const Eigen::Vector3d& gyro) {
  gyro_.add(t, gyro.norm(), options_.window_s);
}

void MotionDetector::addOdometer(double t, double forward_speed) {
  speed_.add(t, forward_speed, options_.window_s);
}

double MotionDetector::meanGyroNorm() const { return gyro_.mean(); }
double MotionDetector::meanSpeed() const { return speed_.mean(); }

bool MotionDetector::isStatic() const {
  return gyro_.full(options_.window_s) && gyro_.mean() < options_.zupt_max_gyro;
}

bool MotionDetector::nhcApplies() const {
  return gyro_.full(options_.window_s) && speed_.full(options_.window_s) &&
         gyro_.mean() < options_.nhc_max_gyro && speed_.mean() > options_.nhc_min_speed;
}

}  // namespace giocal
