#include "common/imu/gyro_mean.h"

#include <algorithm>
#include <cmath>

namespace giocal {

GyroMean meanGyro(const std::vector<ImuSample>& imu, double t, double half_window, double density) {
  auto it = std::lower_bound(imu.begin(), imu.end(), t - half_window,
                             [](const ImuSample& s, double x) { return s.t < x; });
  GyroMean m;
  int n = 0;
  for (; it != imu.end() && it->t <= t + half_window; ++it, ++n) m.rate += it->gyro;
  const double dt =
      imu.size() > 1 ? (imu.back().t - imu.front().t) / static_cast<double>(imu.size() - 1) : 0.01;
  if (n == 0) {
    const auto near = std::min_element(imu.begin(), imu.end(), [&](const auto& a, const auto& b) {
      return std::abs(a.t - t) < std::abs(b.t - t);
    });
    return {near->gyro, density * density / dt};
  }
  m.rate /= n;
  m.variance = density * density / dt / n;
  return m;
}

}  // namespace giocal
