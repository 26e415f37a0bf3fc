#include "common/calibration/dataset_diagnosis.h"

#include <algorithm>
#include <cmath>

#include "common/gnss/broadcast_orbits.h"
#include "common/time/gps_time.h"

namespace giocal {

namespace {

std::string when(double t) { return formatCalendar(calendarFromGpsSeconds(t), 0) + " GPST"; }

std::string span(const ObsData& d) {
  return d.epochs.empty() ? std::string("no epochs")
                          : when(d.epochs.front().t) + " to " + when(d.epochs.back().t);
}

bool hasPhase(const ObsData& d) {
  for (const ObsEpoch& e : d.epochs) {
    for (const SatObs& s : e.sats) {
      for (const SignalObs& g : s.signals) {
        if (std::isfinite(g.L)) return true;
      }
    }
  }
  return false;
}

}  // namespace

std::vector<std::string> diagnoseDataset(const DatasetFiles& f) {
  std::vector<std::string> out;
  if (!f.base.epochs.empty() && !f.rover.epochs.empty()) {
    BaseEpochMatcher match(f.base.epochs, f.max_base_offset);
    int common = 0;
    for (const ObsEpoch& e : f.rover.epochs) common += match.nearest(e.t) != nullptr;
    if (common == 0) {
      out.push_back(f.rover_path + " and " + f.base_path + " have no epoch within " +
                    std::to_string(f.max_base_offset).substr(0, 3) + " s of each other (rover " +
                    span(f.rover) + ", base " + span(f.base) + ")");
    }
  }
  if (!f.rover.epochs.empty()) {
    const BroadcastOrbits orbits(f.nav);
    long with = 0;
    for (std::size_t k = 0; k < f.rover.epochs.size(); k += 10) {
      const ObsEpoch& e = f.rover.epochs[k];
      for (const SatObs& s : e.sats) with += orbits.select(s.sat, e.t) != nullptr;
    }
    if (with == 0) {
      std::string nav_span = "none";
      if (!f.nav.ephemerides.empty()) {
        const auto [lo, hi] = std::minmax_element(
            f.nav.ephemerides.begin(), f.nav.ephemerides.end(),
            [](const Ephemeris& a, const Ephemeris& b) { return a.toe < b.toe; });
        nav_span = "reference times " + when(lo->toe) + " to " + when(hi->toe);
      }
      out.push_back(f.nav_path + ": no broadcast ephemeris valid for the satellites " +
                    f.rover_path + " observes (rover " + span(f.rover) +
                    "; ephemerides: " + nav_span + ")");
    }
  }
  if (!f.rover.epochs.empty() && !hasPhase(f.rover)) {
    out.push_back(f.rover_path +
                  ": no carrier phase (code only): RTK and the double-difference "
                  "phase need it");
  }
  if (!f.base.epochs.empty() && !hasPhase(f.base)) {
    out.push_back(f.base_path + ": no carrier phase (code only)");
  }
  double fastest = 0.0;
  for (const OdomSample& s : f.odom) fastest = std::max(fastest, std::abs(s.v));
  if (fastest < 0.05) {
    out.push_back(f.odom_path + ": the odometer never shows motion (largest speed " +
                  std::to_string(fastest).substr(0, 5) + " m/s): a drive is needed to calibrate");
  }
  return out;
}

}  // namespace giocal
