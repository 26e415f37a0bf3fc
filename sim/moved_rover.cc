#include "sim/moved_rover.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/geodesy/wgs84.h"
#include "sim/sky_geometry.h"

namespace giocal::sim {

namespace {

// Zenith wet delay of the simulator's troposphere; the move changes the height by metres, so
// only the part that scales with height matters and the wet part's size does not.
constexpr double kZenithWet = 0.1;  // [m]

// The receiver's clock offset at an epoch from its codes at the known position (the median over
// signals; the atmosphere's metres are nanoseconds), 0 without codes. Its observations were taken
// at the time tag less this, when the moved antenna must be where the path puts it: a receiver
// that steers its clock loosely (the GSI pair's tags run up to 5 ms off) would otherwise be
// moved 7 mm off at 1.5 m/s.
double clockOffset(const ObsEpoch& e, const BroadcastOrbits& orbits, const Eigen::Vector3d& p) {
  std::vector<double> offsets;
  for (const SatObs& so : e.sats) {
    for (const SignalObs& s : so.signals) {
      Geometry g;
      if (std::isfinite(s.P) && carrierFrequency(so.sat.sys, s.band) > 0.0 &&
          geometry(orbits, so.sat, e.t, p, Eigen::Vector3d::Zero(), s.band, g)) {
        offsets.push_back((s.P - g.range) / kSpeedOfLight + g.clock);
      }
    }
  }
  if (offsets.empty()) return 0.0;
  std::nth_element(offsets.begin(), offsets.begin() + offsets.size() / 2, offsets.end());
  return offsets[offsets.size() / 2];
}

}  // namespace

MovedRover moveStaticRover(const std::vector<ObsEpoch>& rover, const BroadcastOrbits& orbits,
                           const Eigen::Vector3d& static_e, const AntennaTruth& path,
                           double t_begin, double t_end) {
  MovedRover out;
  const double h_static = geodeticFromEcef(static_e).h;
  const Eigen::Vector3d still = Eigen::Vector3d::Zero();
  for (const ObsEpoch& e : rover) {
    if (e.t < t_begin - 1e-6 || e.t > t_end + 1e-6) continue;
    const double t = e.t - clockOffset(e, orbits, static_e);  // the true reception time
    Eigen::Vector3d p, v;
    path(t, p, v);
    const double h = geodeticFromEcef(p).h;
    ObsEpoch moved = e;
    moved.sats.clear();
    for (const SatObs& so : e.sats) {
      SatObs ms;
      ms.sat = so.sat;
      if (!orbits.select(so.sat, t)) {
        ++out.no_ephemeris;
        continue;
      }
      for (const SignalObs& s : so.signals) {
        const double f = carrierFrequency(so.sat.sys, s.band);
        Geometry at_rest, on_path;
        if (f <= 0.0 || !geometry(orbits, so.sat, t, static_e, still, s.band, at_rest) ||
            !geometry(orbits, so.sat, t, p, v, s.band, on_path)) {
          ++out.unsupported_signals;
          continue;
        }
        const double d_range = on_path.range - at_rest.range +
                               troposphere(h, on_path.el, kZenithWet) -
                               troposphere(h_static, at_rest.el, kZenithWet);
        const double lambda = kSpeedOfLight / f;
        SignalObs m = s;
        m.P += d_range;  // NaN stays NaN: a signal without code keeps none
        m.L += d_range / lambda;
        m.D -= (on_path.range_rate - at_rest.range_rate) / lambda;
        ms.signals.push_back(m);
        ++out.signals;
        out.max_move = std::max(out.max_move, std::abs(d_range));
      }
      if (!ms.signals.empty()) moved.sats.push_back(ms);
    }
    out.epochs.push_back(moved);
  }
  return out;
}

}  // namespace giocal::sim
