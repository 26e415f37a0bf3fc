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

// Position, velocity and eccentric anomaly (with its rate) from the Keplerian elements; the
// velocity is the time derivative of the ICD's position equations term by term (it was a central
// difference of three position evaluations, two thirds of the cost of every satellite state).
struct KeplerState {
  Eigen::Vector3d p, v;
  double E = 0.0, E_dot = 0.0;
};

KeplerState keplerState(const Ephemeris& eph, double t) {
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
  KeplerState out;
  out.E = E;
  const double sin_E = std::sin(E), cos_E = std::cos(E);
  const double one_e = 1.0 - eph.e * cos_E;
  out.E_dot = n / one_e;
  const double root = std::sqrt(1.0 - eph.e * eph.e);
  const double nu = std::atan2(root * sin_E, cos_E - eph.e);
  const double phi_dot = out.E_dot * root / one_e;  // d nu / dt
  const double phi = nu + eph.omega;
  const double s2 = std::sin(2 * phi), c2 = std::cos(2 * phi);
  const double u = phi + eph.cus * s2 + eph.cuc * c2;
  const double r = A * one_e + eph.crs * s2 + eph.crc * c2;
  const double i = eph.i0 + eph.cis * s2 + eph.cic * c2 + eph.idot * tk;
  const double u_dot = phi_dot * (1.0 + 2.0 * (eph.cus * c2 - eph.cuc * s2));
  const double r_dot =
      A * eph.e * sin_E * out.E_dot + 2.0 * phi_dot * (eph.crs * c2 - eph.crc * s2);
  const double i_dot = eph.idot + 2.0 * phi_dot * (eph.cis * c2 - eph.cic * s2);
  const double cos_u = std::cos(u), sin_u = std::sin(u), cos_i = std::cos(i), sin_i = std::sin(i);
  const double x = r * cos_u, y = r * sin_u;
  const double x_dot = r_dot * cos_u - r * u_dot * sin_u;
  const double y_dot = r_dot * sin_u + r * u_dot * cos_u;
  // The orbital plane rotated about the node by the inclination and about z by Om.
  const auto rotate = [&](double Om, double Om_dot) {
    const double cO = std::cos(Om), sO = std::sin(Om);
    out.p = {x * cO - y * cos_i * sO, x * sO + y * cos_i * cO, y * sin_i};
    out.v = {x_dot * cO - y_dot * cos_i * sO + y * sin_i * i_dot * sO - Om_dot * out.p.y(),
             x_dot * sO + y_dot * cos_i * cO - y * sin_i * i_dot * cO + Om_dot * out.p.x(),
             y_dot * sin_i + y * cos_i * i_dot};
  };
  // BeiDou time is GPS time minus 14 s; toe is kept in GPS seconds, so the "seconds of week" the
  // ICD uses for Omega differ by 14 s from GPS's.
  const double toe_sow =
      weekTimeFromGpsSeconds(eph.toe - (eph.sat.sys == GnssSystem::kBeidou ? 14.0 : 0.0)).tow;
  if (isBeidouGeo(eph.sat)) {
    rotate(eph.omega0 + eph.omega_dot * tk - c.omega_e * toe_sow, eph.omega_dot);
    // The ICD's R_Z(omega_e tk) R_X(-5 deg) are frame (passive) rotations: active rotations by
    // -omega_e tk about z and +5 deg about x; the first turns with time.
    const double deg5 = 5.0 * M_PI / 180.0;
    const Eigen::Matrix3d Rz = expSO3(Eigen::Vector3d(0, 0, -c.omega_e * tk));
    const Eigen::Matrix3d Rx = expSO3(Eigen::Vector3d(deg5, 0, 0));
    out.p = Rz * (Rx * out.p);
    out.v = Rz * (Rx * out.v) + Eigen::Vector3d(0, 0, -c.omega_e).cross(out.p);
    return out;
  }
  rotate(eph.omega0 + (eph.omega_dot - c.omega_e) * tk - c.omega_e * toe_sow,
         eph.omega_dot - c.omega_e);
  return out;
}

}  // namespace

double satelliteClockPolynomial(const Ephemeris& eph, double t) {
  const double dt = sinceReference(t, eph.toc);
  return eph.af0 + eph.af1 * dt + eph.af2 * dt * dt;
}

SatelliteState satelliteState(const Ephemeris& eph, double t) {
  SatelliteState s;
  const KeplerState k = keplerState(eph, t);
  s.p_e = k.p;
  s.v_e = k.v;
  constexpr double F = -4.442807633e-10;  // -2 sqrt(mu) / c^2 [s/sqrt(m)]
  const double rel = F * eph.e * eph.sqrt_a * std::sin(k.E);
  const double rel_dot = F * eph.e * eph.sqrt_a * std::cos(k.E) * k.E_dot;
  s.clock = satelliteClockPolynomial(eph, t) + rel;
  s.clock_drift = eph.af1 + 2.0 * eph.af2 * sinceReference(t, eph.toc) + rel_dot;
  s.variance = eph.accuracy > 0.0 ? eph.accuracy * eph.accuracy : 100.0;
  return s;
}

}  // namespace giocal
