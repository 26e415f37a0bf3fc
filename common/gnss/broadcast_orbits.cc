#include "common/gnss/broadcast_orbits.h"

#include <cmath>

#include "common/geodesy/wgs84.h"
#include "common/math/so3.h"

namespace giocal {

namespace {

// Largest |t - toe| for which a broadcast ephemeris is used [s].
double validity(GnssSystem sys) {
  switch (sys) {
    case GnssSystem::kGalileo:
      return 14400.0;
    case GnssSystem::kBeidou:
      return 21600.0;
    default:
      return 7200.0 + 60.0;  // GPS/QZSS: fit interval 4 h centred on toe
  }
}

// The satellite's ranging signals are usable. QZSS LNAV's six health bits are one per signal;
// the last flags a signal giocal does not use (LEX/L6 in IS-QZSS 1.x, L1C/B in IS-QZSS-PNT), and
// operating Michibiki satellites broadcast it set (health 1: the mosaic pair's nav file), so it
// is masked, as RTKLIB does. Any other nonzero health excludes the satellite.
bool healthy(const Ephemeris& e) {
  const int mask = e.sat.sys == GnssSystem::kQzss ? ~1 : ~0;
  return (e.health & mask) == 0;
}

}  // namespace

double groupDelay(const Ephemeris& eph, char band) {
  const double f = carrierFrequency(eph.sat.sys, band);
  switch (eph.sat.sys) {
    case GnssSystem::kGps:
    case GnssSystem::kQzss: {
      // The broadcast clock is referenced to the L1/L2 ionosphere-free combination; TGD is the L1
      // delay, and other bands scale with (f1/f)^2.
      const double f1 = carrierFrequency(eph.sat.sys, '1');
      return f > 0.0 ? eph.tgd * (f1 / f) * (f1 / f) : eph.tgd;
    }
    case GnssSystem::kGalileo: {
      // I/NAV clocks are referenced to E1/E5b (BGD E5b/E1 in tgd), F/NAV to E1/E5a (tgd2).
      const bool fnav = (eph.data_source & 2) != 0;
      const double bgd = fnav ? eph.tgd2 : eph.tgd;
      const double f1 = carrierFrequency(eph.sat.sys, '1');
      return f > 0.0 ? bgd * (f1 / f) * (f1 / f) : bgd;
    }
    case GnssSystem::kBeidou:
      // Clocks are referenced to B3I; TGD1 is the B1I delay, TGD2 the B2I delay.
      if (band == '2') return eph.tgd;
      if (band == '7') return eph.tgd2;
      return 0.0;
    default:
      return 0.0;
  }
}

BroadcastOrbits::BroadcastOrbits(const NavData& nav) : nav_(nav) {
  for (const Ephemeris& e : nav_.ephemerides) by_sat_[e.sat].push_back(&e);
}

void BroadcastOrbits::add(const Ephemeris& e) {
  for (const Ephemeris* held : by_sat_[e.sat]) {
    if (held->toe == e.toe && held->data_source == e.data_source) return;
  }
  const Ephemeris* before = nav_.ephemerides.data();
  nav_.ephemerides.push_back(e);
  if (nav_.ephemerides.data() == before) {
    by_sat_[e.sat].push_back(&nav_.ephemerides.back());
    return;
  }
  by_sat_.clear();  // the storage moved
  for (const Ephemeris& x : nav_.ephemerides) by_sat_[x.sat].push_back(&x);
}

void BroadcastOrbits::setIonosphere(const NavData& nav) {
  if (!nav.has_gps_iono) return;
  nav_.gps_iono = nav.gps_iono;
  nav_.has_gps_iono = true;
}

const Ephemeris* BroadcastOrbits::select(const SatId& sat, double t) const {
  const auto it = by_sat_.find(sat);
  if (it == by_sat_.end()) return nullptr;
  const Ephemeris* best = nullptr;
  double best_dt = validity(sat.sys);
  for (const Ephemeris* e : it->second) {
    if (!healthy(*e)) continue;
    // Galileo: prefer I/NAV (E1/E5b) records; F/NAV only when no I/NAV record is near.
    const double penalty =
        (sat.sys == GnssSystem::kGalileo && (e->data_source & 5) == 0) ? 3600.0 : 0.0;
    const double dt = std::abs(t - e->toe) + penalty;
    if (dt <= best_dt) {
      best_dt = dt;
      best = e;
    }
  }
  return best;
}

std::optional<SatelliteAtReception> BroadcastOrbits::atReception(
    const SatId& sat, double t_rx, double range, char band, const Eigen::Vector3d& rx_e) const {
  const Ephemeris* eph = select(sat, t_rx);
  if (!eph) return std::nullopt;
  return atReception(*eph, t_rx, range, band, rx_e);
}

SatelliteAtReception BroadcastOrbits::atReception(const Ephemeris& eph, double t_rx, double range,
                                                  char band, const Eigen::Vector3d& rx_e) {
  return inReceptionFrame(eph, atTransmission(eph, t_rx, range), range, band, rx_e);
}

SatelliteState BroadcastOrbits::atTransmission(const Ephemeris& eph, double t_rx, double range) {
  // Transmission time in GPS time: the tag minus the pseudo-range is the satellite clock's
  // transmission time (both carry the receiver clock error), corrected by the satellite clock.
  double t_tx = t_rx - range / kSpeedOfLight;
  t_tx -= satelliteClockPolynomial(eph, t_tx);
  return satelliteState(eph, t_tx);
}

SatelliteAtReception BroadcastOrbits::inReceptionFrame(const Ephemeris& eph,
                                                       const SatelliteState& s, double range,
                                                       char band, const Eigen::Vector3d& rx_e) {
  // Sagnac: express the transmit-time position in the ECEF frame of reception, rotating by the
  // geometric flight time (iterated once: the rotation changes the range by metres only).
  // The Earth turns by omega tau about z: a rotation by -omega tau.
  const auto earthRotation = [](double tau) {
    return Eigen::AngleAxisd(-wgs84::kOmegaEarth * tau, Eigen::Vector3d::UnitZ())
        .toRotationMatrix();
  };
  double tau = range / kSpeedOfLight;
  if (rx_e.norm() > 1e6) {
    tau = (s.p_e - rx_e).norm() / kSpeedOfLight;
    tau = (earthRotation(tau) * s.p_e - rx_e).norm() / kSpeedOfLight;
  }
  const Eigen::Matrix3d R = earthRotation(tau);
  SatelliteAtReception out;
  out.p_e = R * s.p_e;
  out.v_e = R * s.v_e;
  out.clock = s.clock - groupDelay(eph, band);
  out.clock_drift = s.clock_drift;
  out.variance = s.variance;
  return out;
}

}  // namespace giocal
