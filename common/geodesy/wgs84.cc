#include "common/geodesy/wgs84.h"

#include <cmath>

namespace giocal {

Eigen::Vector3d ecefFromGeodetic(const Geodetic& g) {
  const double s = std::sin(g.lat), c = std::cos(g.lat);
  const double N = wgs84::kA / std::sqrt(1.0 - wgs84::kE2 * s * s);
  return {(N + g.h) * c * std::cos(g.lon), (N + g.h) * c * std::sin(g.lon),
          (N * (1.0 - wgs84::kE2) + g.h) * s};
}

Geodetic geodeticFromEcef(const Eigen::Vector3d& p) {
  // Fixed-point iteration on z + N e^2 sin(lat); converges to 1e-12 m in a handful of steps.
  const double r2 = p.x() * p.x() + p.y() * p.y();
  double z = p.z(), zk = 0.0, N = wgs84::kA;
  for (int i = 0; i < 20 && std::fabs(z - zk) >= 1e-6; ++i) {
    zk = z;
    const double s = z / std::sqrt(r2 + z * z);
    N = wgs84::kA / std::sqrt(1.0 - wgs84::kE2 * s * s);
    z = p.z() + N * wgs84::kE2 * s;
  }
  Geodetic g;
  g.lat = r2 > 1e-12 ? std::atan(z / std::sqrt(r2)) : (p.z() > 0.0 ? M_PI / 2 : -M_PI / 2);
  g.lon = r2 > 1e-12 ? std::atan2(p.y(), p.x()) : 0.0;
  g.h = std::sqrt(r2 + z * z) - N;
  return g;
}

Eigen::Matrix3d rotationEcefFromEnu(double lat, double lon) {
  const double sp = std::sin(lat), cp = std::cos(lat), sl = std::sin(lon), cl = std::cos(lon);
  Eigen::Matrix3d R;
  R.col(0) << -sl, cl, 0.0;
  R.col(1) << -sp * cl, -sp * sl, cp;
  R.col(2) << cp * cl, cp * sl, sp;
  return R;
}

double normalGravity(double lat, double h) {
  constexpr double kGammaE = 9.7803253359;    // normal gravity at the equator [m/s^2]
  constexpr double kSomK = 0.00193185265241;  // Somigliana constant
  constexpr double kM = 0.00344978650684;     // omega^2 a^2 b / GM
  const double s2 = std::sin(lat) * std::sin(lat);
  const double g0 = kGammaE * (1.0 + kSomK * s2) / std::sqrt(1.0 - wgs84::kE2 * s2);
  return g0 * (1.0 - 2.0 / wgs84::kA * (1.0 + wgs84::kF + kM - 2.0 * wgs84::kF * s2) * h +
               3.0 * h * h / (wgs84::kA * wgs84::kA));
}

LocalFrame::LocalFrame(const Eigen::Vector3d& origin_e)
    : origin_e_(origin_e),
      origin_geo_(geodeticFromEcef(origin_e)),
      R_e_n_(rotationEcefFromEnu(origin_geo_.lat, origin_geo_.lon)) {}

Eigen::Vector3d LocalFrame::enuFromEcef(const Eigen::Vector3d& p_e) const {
  return R_e_n_.transpose() * (p_e - origin_e_);
}

Eigen::Vector3d LocalFrame::ecefFromEnu(const Eigen::Vector3d& p_n) const {
  return origin_e_ + R_e_n_ * p_n;
}

Eigen::Vector3d LocalFrame::gravity_n() const {
  return {0.0, 0.0, -normalGravity(origin_geo_.lat, origin_geo_.h)};
}

Eigen::Vector3d LocalFrame::gravity_n(const Eigen::Vector3d& p_n) const {
  const Geodetic g = geodeticFromEcef(ecefFromEnu(p_n));
  const Eigen::Vector3d up_e = rotationEcefFromEnu(g.lat, g.lon).col(2);
  return -normalGravity(g.lat, g.h) * (R_e_n_.transpose() * up_e);
}

Eigen::Vector3d LocalFrame::omega_ie_n() const {
  return R_e_n_.transpose() * Eigen::Vector3d(0.0, 0.0, wgs84::kOmegaEarth);
}

}  // namespace giocal
