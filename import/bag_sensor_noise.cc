#include "import/bag_sensor_noise.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "common/imu/accel_units.h"
#include "common/io/text.h"
#include "common/math/median.h"

namespace giocal::import {

namespace {

// A noise value from a covariance when it lies in the range a real sensor's can, else the default.
double noiseValue(double from_covariance, double lo, double hi, double fallback,
                  const std::string& name, std::vector<std::string>& sources) {
  const bool ok = std::isfinite(from_covariance) && from_covariance >= lo && from_covariance <= hi;
  sources.push_back(name + ": " +
                    (ok ? "message covariance" : "default (covariance absent or implausible)"));
  return ok ? from_covariance : fallback;
}

}  // namespace

void convertAccelUnits(BagDataset& out, std::vector<double>& imu_covariance,
                       const std::string& bag) {
  // sensor_msgs/Imu says m/s^2, but drivers publish g too (a real Husky: mean |f| 1.03).
  const AccelUnit unit = accelUnitOf(out.imu);
  if (!unit.decided) {
    throw std::runtime_error(accelUnitProblem(unit, bag + ": topic " + out.imu_counts.topic));
  }
  out.imu_accel_unit = unit.name;
  if (unit.to_si == 1.0) return;
  for (ImuSample& s : out.imu) s.acc *= unit.to_si;
  for (std::size_t k = 3; k < imu_covariance.size(); ++k)
    if (imu_covariance[k] > 0.0) imu_covariance[k] *= unit.to_si * unit.to_si;
  out.warnings.push_back(bag + ": topic " + out.imu_counts.topic + ": linear_acceleration in " +
                         unit.name + " (mean |f| " + fixedText(unit.mean_norm, 3) +
                         "), not m/s^2: converted (x " + fixedText(unit.to_si, 5) + ")");
}

void setSensorNoise(BagDataset& out, const std::vector<double>& imu_covariance,
                    const std::vector<double>& odom_covariance) {
  std::vector<double> dt;
  for (std::size_t k = 1; k < out.imu.size(); ++k) dt.push_back(out.imu[k].t - out.imu[k - 1].t);
  const double imu_dt = median(dt);
  auto density = [&](const std::vector<double>& c, std::size_t from) {
    if (c.size() < from + 3 || c[from] < 0.0) return std::nan("");  // -1: not provided
    return std::sqrt((c[from] + c[from + 1] + c[from + 2]) / 3.0 * imu_dt);
  };
  ImuNoise& n = out.imu_noise;
  n.gyro_noise_density = noiseValue(density(imu_covariance, 0), 1e-5, 1e-1, n.gyro_noise_density,
                                    "imu gyro_noise_density", out.noise_sources);
  n.accel_noise_density = noiseValue(density(imu_covariance, 3), 1e-4, 1.0, n.accel_noise_density,
                                     "imu accel_noise_density", out.noise_sources);
  out.noise_sources.push_back(
      "imu bias random walks and sigmas: default (ROS messages carry none)");
  OdometerNoise& o = out.odom_noise;
  const auto& c = odom_covariance;
  o.speed_sigma = noiseValue(c.size() == 2 && c[0] > 0 ? std::sqrt(c[0]) : NAN, 1e-4, 1.0,
                             o.speed_sigma, "odometer speed_sigma", out.noise_sources);
  o.yaw_rate_sigma = noiseValue(c.size() == 2 && c[1] > 0 ? std::sqrt(c[1]) : NAN, 1e-4, 1.0,
                                o.yaw_rate_sigma, "odometer yaw_rate_sigma", out.noise_sources);
}

}  // namespace giocal::import
