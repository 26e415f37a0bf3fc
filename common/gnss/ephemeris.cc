#include "common/gnss/ephemeris.h"

#include <cmath>

#include "common/math/so3.h"
#include "common/time/gps_time.h"

namespace giocal {

namespace {

struct Constants {
  double mu, omega_e;
};

Constants constantsOf(GnssSystem sys) {
  switch (sys) {
    case GnssSystem::kGalileo:
      return {3.986004418e14, 7.2921151467e-5};
    case GnssSystem::kBeidou:
      return {3.986004418e14, 7.292115e-5};
    default:  // GPS, QZSS
      return {3.9860050e14, 7.2921151467e-5};
  }
}

// t - t_ref folded into half a week, as the ICDs require for week crossovers.
double sinceReference(double t, double t_ref) {
  double dt = t - t_ref;
  if (dt > kSecondsPerWeek / 2) dt -= kSecondsPerWeek;
  if (dt < -kSecondsPerWeek / 2) dt += kSecondsPerWeek;
  return dt;
}

// Position and eccentric anomaly from the Keplerian elements.
Eigen::Vector3d keplerPosition(const Ephemeris& eph, double t, double& E_out) {
  const Constants c = constantsOf(eph.sat.sys);
  const double A = eph.sqrt_a * eph.sqrt_a;
  const double tk = sinceReference(t, eph.toe);
  const double n = std::sqrt(c.mu / (A * A * A)) + eph.delta_n;
  const double M = eph.m0 + n * tk;
  double E = M;
  for (int i = 0; i < 30; ++i) {
    const double dE = (E - eph.e * std::sin(E) - M) / (1.0 - eph.e * std::cos(E));
    E -= dE;
    if (std::abs(dE) < 1e-14) break;
  }
  E_out = E;
  const double nu = std::atan2(std::sqrt(1.0 - eph.e * eph.e) * std::sin(E), std::cos(E) - eph.e);
  const double phi = nu + eph.omega;
  const double s2 = std::sin(2 * phi), c2 = std::cos(2 * phi);
  const double u = phi + eph.cus * s2 + eph.cuc * c2;
  const double r = A * (1.0 - eph.e * std::cos(E)) + eph.crs * s2 + eph.crc * c2;
  const double i = eph.i0 + eph.cis * s2 + eph.cic * c2 + eph.idot * tk;
  const double x = r * std::cos(u), y = r * std::sin(u);
  // BeiDou time is GPS time minus 14 s; toe is kept in GPS seconds, so the "seconds of week" the
  // ICD uses for Omega differ by 14 s from GPS's.
  const double toe_sow =
      weekTimeFromGpsSeconds(eph.toe - (eph.sat.sys == GnssSystem::kBeidou ? 14.0 : 0.0)).tow;
  if (isBeidouGeo(eph.sat)) {
    const double Om = eph.omega0 + eph.omega_dot * tk - c.omega_e * toe_sow;
    const Eigen::Vector3d p_gk(x * std::cos(Om) - y * std::cos(i) * std::sin(Om),
                               x * std::sin(Om) + y * std::cos(i) * std::cos(Om), y * std::sin(i));
    // The ICD's R_Z(omega_e tk) R_X(-5 deg) are frame (passive) rotations: active rotations by
    // -omega_e tk about z and +5 deg about x.
    const double deg5 = 5.0 * M_PI / 180.0;
    return expSO3(Eigen::Vector3d(0, 0, -c.omega_e * tk)) * expSO3(Eigen::Vector3d(deg5, 0, 0)) *
           p_gk;
  }
  const double Om = eph.omega0 + (eph.omega_dot - c.omega_e) * tk - c.omega_e * toe_sow;
  return {x * std::cos(Om) - y * std::cos(i) * std::sin(Om),
          x * std::sin(Om) + y * std::cos(i) * std::cos(Om), y * std::sin(i)};
}

}  // namespace

double satelliteClockPolynomial(const Ephemeris& eph, double t) {
  const double dt = sinceReference(t, eph.toc);
  return eph.af0 + eph.af1 * dt + eph.af2 * dt * dt;
}

SatelliteState satelliteState(const Ephemeris& eph, double t) {
  SatelliteState s;
  double E = 0.0, E1 = 0.0, E2 = 0.0;
  s.p_e = keplerPosition(eph, t, E);
  // Velocity by central difference: its error (jerk * h^2 / 6) is below 1e-7 m/s for h = 1 ms.
  const double h = 1e-3;
  s.v_e = (keplerPosition(eph, t + h, E1) - keplerPosition(eph, t - h, E2)) / (2 * h);
  constexpr double F = -4.442807633e-10;  // -2 sqrt(mu) / c^2 [s/sqrt(m)]
  const double rel = F * eph.e * eph.sqrt_a * std::sin(E);
  const double rel_dot = F * eph.e * eph.sqrt_a * std::cos(E) * (E1 - E2) / (2 * h);
  s.clock = satelliteClockPolynomial(eph, t) + rel;
  s.clock_drift = eph.af1 + 2.0 * eph.af2 * sinceReference(t, eph.toc) + rel_dot;
  s.variance = eph.accuracy > 0.0 ? eph.accuracy * eph.accuracy : 100.0;
  return s;
}

}  // namespace giocal
