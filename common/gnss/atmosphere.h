// Elevation and azimuth, and the broadcast atmosphere models: Saastamoinen troposphere with a
// standard atmosphere and the Klobuchar ionosphere.
#pragma once

#include <Eigen/Core>
#include <array>

#include "common/geodesy/wgs84.h"

namespace giocal {

/// A receiver's local horizon: elevation and azimuth [rad] of satellites seen from it (ECEF). The
/// receiver's latitude and longitude are found once, not per satellite.
class Topocentric {
 public:
  explicit Topocentric(const Eigen::Vector3d& rx_e);
  void elevationAzimuth(const Eigen::Vector3d& sat_e, double& el, double& az) const;

 private:
  Eigen::Vector3d rx_e_;
  Eigen::Matrix3d R_enu_e_;
};

/// Whether tropoSaastamoinen models a receiver at this height (-100 m to 10 km; else it gives 0).
inline bool tropoModelled(const Geodetic& rx) { return rx.h >= -100.0 && rx.h <= 1e4; }

/// Saastamoinen zenith delay with a standard atmosphere (1013.25 hPa, 15 C, 70 % humidity at sea
/// level) mapped by 1/cos(zenith) [m].
double tropoSaastamoinen(const Geodetic& rx, double el);

/// Klobuchar delay on GPS L1 [m] for GPS time t; scale by (f_L1/f)^2 for other frequencies.
double ionoKlobuchar(const std::array<double, 8>& coeffs, double t, const Geodetic& rx, double el,
                     double az);

}  // namespace giocal
