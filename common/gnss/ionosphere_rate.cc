#include "common/gnss/ionosphere_rate.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <set>
#include <vector>

#include "common/gnss/time_differenced_phase.h"

namespace giocal {

namespace {

// One satellite's signals in a pair (indices): the first band's and, where it has one, the first
// of another band (the geometry-free pair); a third band is corrected with them.
struct SatelliteSignals {
  int a = -1, b = -1;
  std::vector<int> all;
};

std::map<SatId, SatelliteSignals> bySatellite(const TdcpPair& pair) {
  std::map<SatId, SatelliteSignals> out;
  for (int i = 0; i < static_cast<int>(pair.signals.size()); ++i) {
    SatelliteSignals& s = out[pair.signals[i].sat];
    s.all.push_back(i);
    if (s.a < 0) {
      s.a = i;
    } else if (s.b < 0 && pair.signals[i].band != pair.signals[s.a].band) {
      s.b = i;
    }
  }
  return out;
}

// The delay on a signal per metre of delay on the first band: (f_a / f)^2 = (lambda / lambda_a)^2.
double delayRatio(const TdcpSignal& g, const TdcpSignal& a) {
  return (g.lambda / a.lambda) * (g.lambda / a.lambda);
}

}  // namespace

int IonosphereRate::correct(TdcpPair& pair) {
  if (window_s_ <= 0.0) return 0;
  const double dt = pair.t1 - pair.t0;
  // A window shorter than the span asked for would never give a rate.
  const double needed = std::min(min_span_, window_s_);
  std::set<SatId> fed;
  int corrected = 0;
  for (const auto& [sat, s] : bySatellite(pair)) {
    if (s.b < 0) continue;
    const TdcpSignal a = pair.signals[s.a];
    const TdcpSignal b = pair.signals[s.b];
    // The geometry-free phase is (gamma - 1) I_a plus the ambiguities, I_b = gamma I_a.
    const double gamma = delayRatio(b, a);
    const double change_a = (a.phase_change_m - b.phase_change_m) / (gamma - 1.0);
    Track& track = tracks_[sat];
    if (track.empty() || std::abs(track.back().first - pair.t0) > 1e-6) {
      track.assign(1, {pair.t0, 0.0});
    }
    track.emplace_back(pair.t1, track.back().second + change_a);
    while (pair.t1 - track.front().first > window_s_ + 1e-6) track.pop_front();
    fed.insert(sat);
    if (pair.t1 - track.front().first < needed - 1e-6) continue;
    // The straight line through the accumulated delay: each point carries one epoch's
    // geometry-free phase noise (half a time difference's variance per band).
    double t_mean = 0.0, y_mean = 0.0;
    for (const auto& [t, y] : track) {
      t_mean += t;
      y_mean += y;
    }
    const double n = static_cast<double>(track.size());
    t_mean /= n;
    y_mean /= n;
    double sxx = 0.0, sxy = 0.0;
    for (const auto& [t, y] : track) {
      sxx += (t - t_mean) * (t - t_mean);
      sxy += (t - t_mean) * (y - y_mean);
    }
    const double rate = sxy / sxx;
    const double point_variance = 0.5 * (a.variance + b.variance) / ((gamma - 1.0) * (gamma - 1.0));
    const double change_variance = point_variance / sxx * dt * dt;
    // The phase is advanced by the delay: its change plus the delay's change is the range's.
    for (int i : s.all) {
      TdcpSignal& g = pair.signals[static_cast<size_t>(i)];
      const double k = delayRatio(g, a);
      g.phase_change_m += k * rate * dt;
      g.variance += k * k * change_variance;
      ++corrected;
    }
  }
  for (auto it = tracks_.begin(); it != tracks_.end();) {
    it = fed.count(it->first) ? std::next(it) : tracks_.erase(it);
  }
  return corrected;
}

}  // namespace giocal
