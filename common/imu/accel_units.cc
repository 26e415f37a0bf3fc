#include "common/imu/accel_units.h"

#include <cmath>
#include <cstdio>

namespace giocal {

namespace {
constexpr double kStandardGravity = 9.80665;  // [m/s^2]
constexpr double kTolerance = 0.1;            // share of gravity a mean may be off
}  // namespace

AccelUnit accelUnitOf(const std::vector<ImuSample>& imu) {
  AccelUnit u;
  if (imu.empty()) return u;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const ImuSample& s : imu) sum += s.acc;
  u.mean_norm = (sum / static_cast<double>(imu.size())).norm();
  const struct {
    const char* name;
    double gravity;  // in the unit
  } units[] = {{"m/s^2", kStandardGravity}, {"g", 1.0}, {"mg", 1000.0}};
  for (const auto& c : units) {
    if (std::abs(u.mean_norm / c.gravity - 1.0) <= kTolerance) {
      u.decided = true;
      u.name = c.name;
      u.to_si = kStandardGravity / c.gravity;
    }
  }
  return u;
}

std::string accelUnitProblem(const AccelUnit& u, const std::string& where) {
  char mean[64];
  std::snprintf(mean, sizeof(mean), "%.4g", u.mean_norm);
  return where + ": the mean specific force is " + mean +
         ", gravity in none of m/s^2 (9.81), g (1) or mg (1000): not an accelerometer in a known "
         "unit, or a column mix-up";
}

}  // namespace giocal
