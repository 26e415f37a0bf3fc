#include "common/gnss/dd_epoch.h"

#include <algorithm>
#include <cmath>

#include "common/gnss/atmosphere.h"
#include "common/gnss/spp.h"

namespace giocal {

std::vector<GnssSystem> defaultGnssSystems() {
  return {GnssSystem::kGps, GnssSystem::kGalileo, GnssSystem::kBeidou, GnssSystem::kQzss};
}

std::vector<char> ddBands(GnssSystem sys, int frequencies) {
  std::vector<char> b;
  if (sys == GnssSystem::kBeidou) {
    b = {'2', '7', '6'};  // B1I, B2I, B3I
  } else if (sys == GnssSystem::kGalileo) {
    b = {'1', '7', '5'};  // E1, E5b, E5a
  } else {
    b = {'1', '2', '5'};  // L1, L2, L5
  }
  b.resize(static_cast<size_t>(std::clamp(frequencies, 1, 3)));
  return b;
}

DdEpochBuilder::DdEpochBuilder(const BroadcastOrbits& orbits, const Eigen::Vector3d& base_e,
                               const DdOptions& options)
    : orbits_(orbits),
      base_e_(base_e),
      options_(options),
      rover_slips_(options.slips),
      base_slips_(options.slips) {}

DdEpoch DdEpochBuilder::build(const ObsEpoch& rover, const ObsEpoch& base,
                              const Eigen::Vector3d& rover_e) {
  rover_slips_.update(rover);
  base_slips_.update(base);
  DdEpoch out;
  // The satellites as each receiver saw them (the time tags and pseudo-ranges carry the same
  // receiver clock error, so tag minus range is the transmission time for both).
  const double mask = options_.elevation_mask_deg * M_PI / 180.0;
  const Topocentric sky(rover_e), base_sky(base_e_);
  const Geodetic rover_geo = geodeticFromEcef(rover_e), base_geo = geodeticFromEcef(base_e_);
  // Both receivers' troposphere or neither: one modelled against one not (a rover position not
  // yet known, or below the model's -100 m) would put metres into every row.
  const bool tropo = tropoModelled(rover_geo) && tropoModelled(base_geo);
  std::vector<std::pair<const SatObs*, const SatObs*>> pairs;
  for (const SatObs& ro : rover.sats) {
    if (std::find(options_.systems.begin(), options_.systems.end(), ro.sat.sys) ==
        options_.systems.end()) {
      continue;
    }
    const SatObs* bo = base.find(ro.sat);
    if (!bo) continue;
    const SignalObs* rp = ro.bestOnBand(primaryBand(ro.sat.sys));
    const SignalObs* bp = bo->bestOnBand(primaryBand(ro.sat.sys));
    if (!rp || !bp) continue;
    const auto sr = orbits_.atReception(ro.sat, rover.t, rp->P, rp->band, rover_e);
    if (!sr) continue;
    out.rover_satellites.push_back({ro.sat, rp->band, rp->P, *sr});
    const auto sb = orbits_.atReception(ro.sat, base.t, bp->P, bp->band, base_e_);
    if (!sb) continue;
    SdGeometry g;
    g.sat = ro.sat;
    g.sat_at_rover_e = sr->p_e;
    g.base_range = (sb->p_e - base_e_).norm();
    double az = 0.0, base_el = 0.0;
    sky.elevationAzimuth(sr->p_e, g.el, az);
    if (g.el < mask) continue;
    base_sky.elevationAzimuth(sb->p_e, base_el, az);
    if (tropo) {
      g.tropo_sd = tropoSaastamoinen(rover_geo, g.el) - tropoSaastamoinen(base_geo, base_el);
    }
    out.geometry.push_back(g);
    out.undiff_variance.push_back(
        {2.0 * options_.code.variance(g.el), 2.0 * options_.phase.variance(g.el)});
    pairs.push_back({&ro, bo});
  }
  const auto& geometry = out.geometry;
  for (GnssSystem sys : options_.systems) {
    for (char band : ddBands(sys, options_.frequencies)) {
      std::vector<int> cand;
      std::map<int, std::pair<double, double>> sd;  // index -> (SD code, SD phase [m])
      const double lambda = kSpeedOfLight / carrierFrequency(sys, band);
      for (size_t i = 0; i < pairs.size(); ++i) {
        if (geometry[i].sat.sys != sys) continue;
        const SignalObs* r = pairs[i].first->bestOnBand(band);
        const SignalObs* b = pairs[i].second->bestOnBand(band);
        if (!r || !b || std::isnan(r->L) || std::isnan(b->L)) continue;
        const double sd_p = r->P - b->P, sd_l = (r->L - b->L) * lambda;
        const SatId sat = geometry[i].sat;
        out.ambiguities.push_back(
            {sat, band, (sd_l - sd_p) / lambda, lambda,
             rover_slips_.slipped(sat, band) || base_slips_.slipped(sat, band)});
        cand.push_back(static_cast<int>(i));
        sd[static_cast<int>(i)] = {sd_p, sd_l};
      }
      if (cand.size() < 2) continue;
      const auto prev = refs_.find({sys, band});
      int prev_idx = -1;
      for (int i : cand) {
        if (prev != refs_.end() && geometry[static_cast<size_t>(i)].sat == prev->second)
          prev_idx = i;
      }
      const int ref = chooseReference(geometry, cand, prev_idx,
                                      options_.keep_reference_elevation_deg * M_PI / 180.0);
      refs_[{sys, band}] = geometry[static_cast<size_t>(ref)].sat;
      for (int i : cand) {
        if (i == ref) continue;
        for (bool phase : {true, false}) {
          DdObservation o;
          o.sat = geometry[static_cast<size_t>(i)].sat;
          o.ref = geometry[static_cast<size_t>(ref)].sat;
          o.band = band;
          o.phase = phase;
          o.lambda = lambda;
          o.sat_index = i;
          o.ref_index = ref;
          o.value = phase ? sd[i].second - sd[ref].second : sd[i].first - sd[ref].first;
          out.obs.push_back(o);
        }
      }
    }
  }
  return out;
}

}  // namespace giocal
