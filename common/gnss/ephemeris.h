// Broadcast ephemeris (Keplerian elements and clock polynomial) and the satellite position,
// velocity and clock computed from it (IS-GPS-200 Table 20-IV, Galileo OS SIS ICD 5.1.1, BeiDou
// ICD 5.2.4).
#pragma once

#include <Eigen/Core>

#include "common/gnss/satellite.h"

namespace giocal {

struct Ephemeris {
  SatId sat;
  double toc = 0.0;  // clock reference time, GPS seconds (BeiDou records are converted from BDT)
  double toe = 0.0;  // ephemeris reference time, GPS seconds
  double af0 = 0.0, af1 = 0.0, af2 = 0.0;
  double iode = 0.0, iodc = 0.0;
  double crs = 0.0, crc = 0.0, cus = 0.0, cuc = 0.0, cis = 0.0, cic = 0.0;
  double delta_n = 0.0, m0 = 0.0, e = 0.0, sqrt_a = 0.0;
  double omega0 = 0.0, i0 = 0.0, omega = 0.0, omega_dot = 0.0, idot = 0.0;
  double tgd = 0.0;   // GPS/QZSS TGD; Galileo BGD E1/E5b; BeiDou TGD1 (B1I/B3I)
  double tgd2 = 0.0;  // Galileo BGD E1/E5a; BeiDou TGD2 (B2I/B3I)
  int health = 0;
  int data_source = 0;    // Galileo: bit 0 I/NAV E1-B, bit 1 F/NAV E5a-I, bit 2 I/NAV E5b-I
  double accuracy = 0.0;  // URA / SISA [m]
};

struct SatelliteState {
  Eigen::Vector3d p_e = Eigen::Vector3d::Zero();  // ECEF at transmission, in the frame of that time
  Eigen::Vector3d v_e = Eigen::Vector3d::Zero();
  double clock = 0.0;        // satellite clock offset incl. relativistic correction [s], no TGD
  double clock_drift = 0.0;  // [s/s]
  double variance = 0.0;     // ephemeris error variance [m^2]
};

/// Position, velocity and clock at GPS time t (transmission time).
SatelliteState satelliteState(const Ephemeris& eph, double t);

/// Satellite clock at t for the transmission-time iteration (polynomial only, no relativity).
double satelliteClockPolynomial(const Ephemeris& eph, double t);

}  // namespace giocal
