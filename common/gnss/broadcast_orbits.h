// BroadcastOrbits: ephemerides indexed by satellite, selection (nearest toe, healthy, within
// validity) and the satellite seen by a receiver (transmission-time iteration, Sagnac rotation).
#pragma once

#include <map>
#include <optional>
#include <vector>

#include "common/gnss/ephemeris.h"
#include "common/gnss/rinex_nav.h"

namespace giocal {

/// The satellite as a receiver sees it at reception time: position rotated into the ECEF frame of
/// reception (Sagnac), clock (with relativity and the group delay of the signal's band) and the
/// state's velocity and drift for Doppler.
struct SatelliteAtReception {
  Eigen::Vector3d p_e = Eigen::Vector3d::Zero(), v_e = Eigen::Vector3d::Zero();
  double clock = 0.0;        // [s], to add to the geometric range times c
  double clock_drift = 0.0;  // [s/s]
  double variance = 0.0;     // ephemeris error variance [m^2]
};

class BroadcastOrbits {
 public:
  explicit BroadcastOrbits(const NavData& nav);

  /// Healthy ephemeris with toe nearest t within the system's validity; nullptr when none.
  const Ephemeris* select(const SatId& sat, double t) const;

  /// The satellite for a signal tagged t_rx by the receiver clock with pseudo-range `range` on
  /// `band`. t_rx - range / c is the transmission time whatever the receiver clock error (the
  /// pseudo-range carries the same error). The Earth rotation during the flight uses the geometric
  /// travel time from `rx_e` (the receiver's approximate ECEF position; zero: use range / c, which
  /// is wrong by the receiver clock error). Empty when no ephemeris applies.
  std::optional<SatelliteAtReception> atReception(const SatId& sat, double t_rx, double range,
                                                  char band, const Eigen::Vector3d& rx_e) const;
  /// The same with a chosen ephemeris (a time-differenced pair computes both epochs with one).
  static SatelliteAtReception atReception(const Ephemeris& eph, double t_rx, double range,
                                          char band, const Eigen::Vector3d& rx_e);
  /// atReception in two steps: the satellite at its transmission time, which depends on the
  /// tag and the pseudo-range only, then turned into the frame of reception from `rx_e` (an
  /// iterated position fix computes the first once per satellite).
  static SatelliteState atTransmission(const Ephemeris& eph, double t_rx, double range);
  static SatelliteAtReception inReceptionFrame(const Ephemeris& eph, const SatelliteState& s,
                                               double range, char band,
                                               const Eigen::Vector3d& rx_e);

  const NavData& nav() const { return nav_; }
  /// A navigation message received later (online); one already held (same satellite and toe) is
  /// ignored (as mergeNav() does). The ionosphere parameters are taken when `nav` has them.
  void add(const Ephemeris& e);
  void setIonosphere(const NavData& nav);

 private:
  NavData nav_;
  std::map<SatId, std::vector<const Ephemeris*>> by_sat_;
};

/// Group delay of the broadcast clock for a single-frequency user of `band` [s] (IS-GPS-200
/// 20.3.3.3.3.2, Galileo OS SIS ICD 5.1.5, BeiDou ICD 5.2.4.10).
double groupDelay(const Ephemeris& eph, char band);

}  // namespace giocal
