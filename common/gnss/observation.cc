#include "common/gnss/observation.h"

#include <cmath>
#include <string>

namespace giocal {

int attributeRank(char attr) {
  // Attributes in order of preference: civil/open codes first, then semi-codeless, then the rest.
  static const std::string kOrder = "CWPLSXQIDBZAM";
  const auto pos = kOrder.find(attr);
  return static_cast<int>(pos == std::string::npos ? 50 : pos);
}

const SignalObs* SatObs::bestOnBand(char band) const {
  const SignalObs* best = nullptr;
  int best_rank = 1 << 20;
  for (const SignalObs& s : signals) {
    if (s.band != band || std::isnan(s.P)) continue;
    const int rank = (std::isnan(s.L) ? 100 : 0) + attributeRank(s.attr);
    if (rank < best_rank) {
      best_rank = rank;
      best = &s;
    }
  }
  return best;
}

const SatObs* ObsEpoch::find(const SatId& sat) const {
  for (const SatObs& s : sats) {
    if (s.sat == sat) return &s;
  }
  return nullptr;
}

const ObsEpoch* BaseEpochMatcher::nearest(double t) {
  if (base_.empty()) return nullptr;
  while (k_ + 1 < base_.size() && std::abs(base_[k_ + 1].t - t) <= std::abs(base_[k_].t - t)) ++k_;
  return std::abs(base_[k_].t - t) <= max_offset_ ? &base_[k_] : nullptr;
}

}  // namespace giocal
