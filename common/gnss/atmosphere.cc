#include "common/gnss/atmosphere.h"

#include <cmath>

#include "common/gnss/satellite.h"
#include "common/time/gps_time.h"

namespace giocal {

Topocentric::Topocentric(const Eigen::Vector3d& rx_e) : rx_e_(rx_e) {
  const Geodetic g = geodeticFromEcef(rx_e);
  R_enu_e_ = rotationEcefFromEnu(g.lat, g.lon).transpose();
}

void Topocentric::elevationAzimuth(const Eigen::Vector3d& sat_e, double& el, double& az) const {
  const Eigen::Vector3d los = R_enu_e_ * (sat_e - rx_e_).normalized();
  el = std::asin(std::clamp(los.z(), -1.0, 1.0));
  az = std::atan2(los.x(), los.y());
  if (az < 0) az += 2 * M_PI;
}

double tropoSaastamoinen(const Geodetic& rx, double el) {
  if (!tropoModelled(rx) || el <= 0.0) return 0.0;
  const double h = std::max(rx.h, 0.0);
  // Standard atmosphere at height h.
  const double p = 1013.25 * std::pow(1.0 - 2.2557e-5 * h, 5.2568);
  const double T = 15.0 - 6.5e-3 * h + 273.16;
  const double e = 6.108 * 0.7 * std::exp((17.15 * T - 4684.0) / (T - 38.45));
  const double z = M_PI / 2.0 - el;
  const double dry =
      0.0022768 * p / (1.0 - 0.00266 * std::cos(2.0 * rx.lat) - 0.00028 * h / 1e3) / std::cos(z);
  const double wet = 0.002277 * (1255.0 / T + 0.05) * e / std::cos(z);
  return dry + wet;
}

double ionoKlobuchar(const std::array<double, 8>& a, double t, const Geodetic& rx, double el,
                     double az) {
  // IS-GPS-200 20.3.3.5.2.5, angles in semicircles.
  const double E = el / M_PI;
  const double psi = 0.0137 / (E + 0.11) - 0.022;
  double phi_i = rx.lat / M_PI + psi * std::cos(az);
  phi_i = std::clamp(phi_i, -0.416, 0.416);
  const double lam_i = rx.lon / M_PI + psi * std::sin(az) / std::cos(phi_i * M_PI);
  const double phi_m = phi_i + 0.064 * std::cos((lam_i - 1.617) * M_PI);
  double tl = 43200.0 * lam_i + weekTimeFromGpsSeconds(t).tow;
  tl -= std::floor(tl / 86400.0) * 86400.0;
  const double F = 1.0 + 16.0 * std::pow(0.53 - E, 3);
  double amp = a[0] + phi_m * (a[1] + phi_m * (a[2] + phi_m * a[3]));
  double per = a[4] + phi_m * (a[5] + phi_m * (a[6] + phi_m * a[7]));
  amp = std::max(amp, 0.0);
  per = std::max(per, 72000.0);
  const double x = 2.0 * M_PI * (tl - 50400.0) / per;
  const double delay =
      std::abs(x) < 1.57 ? 5e-9 + amp * (1.0 - x * x / 2.0 + x * x * x * x / 24.0) : 5e-9;
  return kSpeedOfLight * F * delay;
}

}  // namespace giocal
