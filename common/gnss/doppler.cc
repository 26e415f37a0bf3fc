#include "common/gnss/doppler.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "common/geodesy/wgs84.h"
#include "common/gnss/atmosphere.h"

namespace giocal {

std::vector<DopplerObservation> dopplerObservations(const ObsEpoch& epoch,
                                                    const BroadcastOrbits& orbits,
                                                    const Eigen::Vector3d& rover_e,
                                                    const DopplerOptions& options,
                                                    const std::vector<RoverSatellite>& known) {
  std::vector<DopplerObservation> out;
  const double mask = options.elevation_mask_deg * M_PI / 180.0;
  const Topocentric sky(rover_e);
  for (const SatObs& so : epoch.sats) {
    if (std::find(options.systems.begin(), options.systems.end(), so.sat.sys) ==
        options.systems.end()) {
      continue;
    }
    const char band = primaryBand(so.sat.sys);
    const SignalObs* sig = nullptr;
    for (const SignalObs& s : so.signals) {
      if (s.band == band && std::isfinite(s.D) && std::isfinite(s.P)) {
        sig = &s;
        break;
      }
    }
    if (!sig) continue;
    const auto k = std::find_if(known.begin(), known.end(), [&](const RoverSatellite& r) {
      return r.sat == so.sat && r.band == band && r.code == sig->P;
    });
    const auto sr = k != known.end() ? std::optional<SatelliteAtReception>(k->at)
                                     : orbits.atReception(so.sat, epoch.t, sig->P, band, rover_e);
    if (!sr) continue;
    DopplerObservation d;
    d.sat = so.sat;
    double az = 0.0;
    sky.elevationAzimuth(sr->p_e, d.el, az);
    if (d.el < mask) continue;
    d.los_e = (sr->p_e - rover_e).normalized();
    // Rate of the Sagnac term omega/c (x_s y_r - y_s x_r) from the satellite's motion alone; the
    // receiver's share is below 1e-5 of its speed.
    const double sagnac_rate = wgs84::kOmegaEarth / kSpeedOfLight *
                               (sr->v_e.y() * rover_e.x() - sr->v_e.x() * rover_e.y());
    d.satellite_term = d.los_e.dot(sr->v_e) - kSpeedOfLight * sr->clock_drift + sagnac_rate;
    d.range_rate = -kSpeedOfLight / carrierFrequency(so.sat.sys, band) * sig->D;
    d.variance = options.noise.variance(d.el);
    out.push_back(d);
  }
  return out;
}

}  // namespace giocal
