#include "common/gnss/code_outlier_check.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/math/sorted_by_key.h"

namespace giocal {

std::set<CodeOutlierCheck::Key> CodeOutlierCheck::check(const ObsEpoch& epoch) {
  std::vector<Candidate>& cands = cands_;
  cands.clear();
  for (const SatObs& so : epoch.sats) {
    for (const SignalObs& s : so.signals) {
      if (!std::isfinite(s.P) || !std::isfinite(s.D)) continue;
      const Key key{so.sat, s.band};
      const double rate = -kSpeedOfLight / carrierFrequency(so.sat.sys, s.band) * s.D;
      Candidate c{key, s.P, rate, 0.0, false};
      const auto it = findKey(tracks_, key);
      if (it != tracks_.end()) {
        const double dt = epoch.t - it->second.t;
        if (dt > 0.0 && dt <= options_.max_gap_s) {
          c.jump = s.P - (it->second.P + 0.5 * (it->second.range_rate + rate) * dt);
          c.tracked = true;
        }
      }
      cands.push_back(c);
    }
  }
  // One signal per band, the first listed: sorted by key, the first of each key kept.
  const auto by_key = [](const Candidate& a, const Candidate& b) { return a.key < b.key; };
  std::stable_sort(cands.begin(), cands.end(), by_key);
  cands.erase(std::unique(cands.begin(), cands.end(),
                          [](const Candidate& a, const Candidate& b) { return a.key == b.key; }),
              cands.end());
  // The receiver clock moves every pseudo-range alike: take the median jump as common.
  std::vector<double>& jumps = jumps_;
  jumps.clear();
  for (const Candidate& c : cands) {
    if (c.tracked) jumps.push_back(c.jump);
  }
  const bool decide = static_cast<int>(jumps.size()) >= options_.min_satellites;
  double common = 0.0;
  if (decide) {
    std::nth_element(jumps.begin(), jumps.begin() + static_cast<long>(jumps.size() / 2),
                     jumps.end());
    common = jumps[jumps.size() / 2];
  }
  std::set<Key> outliers;
  next_.clear();
  for (const Candidate& c : cands) {
    Track tr{epoch.t, c.P, c.range_rate, 0};
    if (decide && c.tracked && std::abs(c.jump - common) > options_.threshold_m) {
      const Track& old = findKey(tracks_, c.key)->second;
      if (old.rejected_in_row + 1 < options_.max_consecutive) {
        outliers.insert(c.key);
        // Keep predicting from the last good value so one outlier does not poison the next epoch.
        tr.P = c.P - c.jump + common;
        tr.rejected_in_row = old.rejected_in_row + 1;
      }
    }
    next_.push_back({c.key, tr});
  }
  // Tracks unseen this epoch are kept a while.
  const auto seen = static_cast<std::ptrdiff_t>(next_.size());
  for (const auto& entry : tracks_) {
    if (epoch.t - entry.second.t <= options_.max_gap_s &&
        !std::binary_search(next_.begin(), next_.begin() + seen, entry, ByKey())) {
      next_.push_back(entry);
    }
  }
  std::inplace_merge(next_.begin(), next_.begin() + seen, next_.end(), ByKey());
  std::swap(tracks_, next_);
  return outliers;
}

}  // namespace giocal
