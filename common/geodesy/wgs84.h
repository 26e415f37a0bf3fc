// WGS84 ellipsoid: ECEF <-> geodetic, the ENU rotation R_e_n, normal gravity, Earth rotation.
#pragma once

#include <Eigen/Core>

namespace giocal {

namespace wgs84 {
constexpr double kA = 6378137.0;                 // semi-major axis [m]
constexpr double kF = 1.0 / 298.257223563;       // flattening
constexpr double kE2 = kF * (2.0 - kF);          // first eccentricity squared
constexpr double kOmegaEarth = 7.2921151467e-5;  // Earth rotation rate [rad/s]
constexpr double kGM = 3.986004418e14;           // gravitational constant [m^3/s^2]
}  // namespace wgs84

/// Latitude, longitude [rad] and ellipsoidal height [m].
struct Geodetic {
  double lat = 0.0;
  double lon = 0.0;
  double h = 0.0;
};

Eigen::Vector3d ecefFromGeodetic(const Geodetic& g);

/// Exact to well below a millimetre for heights from -10 km to GNSS orbit altitudes.
Geodetic geodeticFromEcef(const Eigen::Vector3d& p_e);

/// Columns are the east, north and up axes in ECEF: x_e = R_e_n x_n.
Eigen::Matrix3d rotationEcefFromEnu(double lat, double lon);

/// Magnitude of normal gravity (Somigliana, with the WGS84 second-order height correction) [m/s^2].
double normalGravity(double lat, double h);

/// A local ENU frame n anchored at an ECEF origin (the dataset origin, normally the base).
class LocalFrame {
 public:
  explicit LocalFrame(const Eigen::Vector3d& origin_e);

  const Eigen::Vector3d& origin_e() const { return origin_e_; }
  const Geodetic& originGeodetic() const { return origin_geo_; }
  const Eigen::Matrix3d& R_e_n() const { return R_e_n_; }

  Eigen::Vector3d enuFromEcef(const Eigen::Vector3d& p_e) const;
  Eigen::Vector3d ecefFromEnu(const Eigen::Vector3d& p_n) const;

  /// Gravity vector in n at the origin (points down).
  Eigen::Vector3d gravity_n() const;
  /// Normal gravity vector in n at the point p_n (along that point's ellipsoid normal; 100 m from
  /// the origin it tilts by 1.6e-5 rad from the origin's vertical).
  Eigen::Vector3d gravity_n(const Eigen::Vector3d& p_n) const;
  /// Earth rotation rate expressed in n.
  Eigen::Vector3d omega_ie_n() const;

 private:
  Eigen::Vector3d origin_e_;
  Geodetic origin_geo_;
  Eigen::Matrix3d R_e_n_;
};

}  // namespace giocal
