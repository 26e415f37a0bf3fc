#include "sim/sky_geometry.h"

#include <cmath>

#include "common/geodesy/wgs84.h"
#include "common/math/so3.h"

namespace giocal::sim {

bool geometry(const BroadcastOrbits& orbits, const SatId& sat, double t_rx,
              const Eigen::Vector3d& p, const Eigen::Vector3d& v, char band, Geometry& g) {
  const Ephemeris* eph = orbits.select(sat, t_rx);
  if (!eph) return false;
  double tau = 0.075;
  SatelliteState s;
  Eigen::Vector3d ps, vs;
  for (int i = 0; i < 4; ++i) {
    s = satelliteState(*eph, t_rx - tau);
    const Eigen::Matrix3d R = expSO3(Eigen::Vector3d(0, 0, -wgs84::kOmegaEarth * tau));
    ps = R * s.p_e;
    vs = R * s.v_e;
    tau = (ps - p).norm() / kSpeedOfLight;
  }
  const Eigen::Vector3d u = (ps - p) / (ps - p).norm();
  g.u = u;
  g.range = (ps - p).norm();
  g.range_rate = u.dot(vs - v);
  g.clock = s.clock - groupDelay(*eph, band);
  g.clock_drift = s.clock_drift;
  const Geodetic geo = geodeticFromEcef(p);
  const Eigen::Vector3d los = rotationEcefFromEnu(geo.lat, geo.lon).transpose() * u;
  g.el = std::asin(los.z());
  g.az = std::atan2(los.x(), los.y());
  return true;
}

double troposphere(double h, double el, double zwd) {
  const double zhd = 2.3 * std::exp(-h / 7000.0);
  return (zhd + zwd) * 1.001 / std::sqrt(0.002001 + std::sin(el) * std::sin(el));
}

}  // namespace giocal::sim
