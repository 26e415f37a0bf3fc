#include "common/gnss/ionosphere_rate.h"

#include <set>

#include "common/gnss/time_differenced_phase.h"

namespace giocal {

namespace {

// The two signals of one satellite on different bands in a pair (indices), the first band first.
struct BandPair {
  int a = -1, b = -1;
};

std::map<SatId, BandPair> bandPairs(const TdcpPair& pair) {
  std::map<SatId, BandPair> out;
  for (int i = 0; i < static_cast<int>(pair.signals.size()); ++i) {
    BandPair& p = out[pair.signals[i].sat];
    if (p.a < 0) {
      p.a = i;
    } else if (p.b < 0 && pair.signals[i].band != pair.signals[p.a].band) {
      p.b = i;
    }
  }
  return out;
}

}  // namespace

int IonosphereRate::correct(TdcpPair& pair) {
  if (window_s_ <= 0.0) return 0;
  const double dt = pair.t1 - pair.t0;
  std::set<SatId> fed;
  int corrected = 0;
  for (const auto& [sat, p] : bandPairs(pair)) {
    if (p.b < 0) continue;
    TdcpSignal& a = pair.signals[p.a];
    TdcpSignal& b = pair.signals[p.b];
    // I_b = gamma I_a, and the geometry-free phase is (gamma - 1) I_a plus the ambiguities.
    const double gamma = (b.lambda / a.lambda) * (b.lambda / a.lambda);
    const double change_a = (a.phase_change_m - b.phase_change_m) / (gamma - 1.0);
    Track& track = tracks_[sat];
    if (track.delay.empty() || std::abs(track.delay.back().first - pair.t0) > 1e-6) {
      track.delay.assign(1, {pair.t0, 0.0});
    }
    track.delay.emplace_back(pair.t1, track.delay.back().second + change_a);
    while (pair.t1 - track.delay.front().first > window_s_ + 1e-6) track.delay.pop_front();
    fed.insert(sat);
    if (pair.t1 - track.delay.front().first < min_span_ - 1e-6) continue;
    // The straight line through the accumulated delay: each point carries one epoch's
    // geometry-free phase noise (half a time difference's variance per band).
    double t_mean = 0.0, y_mean = 0.0;
    for (const auto& [t, y] : track.delay) {
      t_mean += t;
      y_mean += y;
    }
    const double n = static_cast<double>(track.delay.size());
    t_mean /= n;
    y_mean /= n;
    double sxx = 0.0, sxy = 0.0;
    for (const auto& [t, y] : track.delay) {
      sxx += (t - t_mean) * (t - t_mean);
      sxy += (t - t_mean) * (y - y_mean);
    }
    const double rate = sxy / sxx;
    const double point_variance = 0.5 * (a.variance + b.variance) / ((gamma - 1.0) * (gamma - 1.0));
    const double change_variance = point_variance / sxx * dt * dt;
    // The phase is advanced by the delay: its change plus the delay's change is the range's.
    a.phase_change_m += rate * dt;
    b.phase_change_m += gamma * rate * dt;
    a.variance += change_variance;
    b.variance += gamma * gamma * change_variance;
    corrected += 2;
  }
  for (auto it = tracks_.begin(); it != tracks_.end();) {
    it = fed.count(it->first) ? std::next(it) : tracks_.erase(it);
  }
  return corrected;
}

}  // namespace giocal
