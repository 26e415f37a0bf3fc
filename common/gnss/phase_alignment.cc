#include "common/gnss/phase_alignment.h"

#include <cmath>
#include <cstdio>

namespace giocal {

namespace {

std::string cyclesText(double c) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%+.2f", c);
  return buf;
}

}  // namespace

bool hasSeveralPhasesOnABand(const ObsHeader& h) {
  for (const auto& [sys, types] : h.obs_types) {
    std::map<char, int> per_band;
    for (const std::string& t : types) {
      if (t.size() == 3 && t[0] == 'L' && ++per_band[t[1]] > 1) return true;
    }
  }
  return false;
}

bool PhaseAlignment::add(const ObsEpoch& e) {
  bool judgeable = false;
  for (const SatObs& s : e.sats) {
    for (const SignalObs& a : s.signals) {
      if (std::isnan(a.L) || (a.lli & 2)) continue;  // an unresolved half cycle says nothing
      for (const SignalObs& r : s.signals) {
        if (&r == &a || r.band != a.band || std::isnan(r.L) || (r.lli & 2) ||
            attributeRank(r.attr) >= attributeRank(a.attr)) {
          continue;
        }
        // Each tracking loop counts its own integer: only the fraction of a cycle is compared.
        const double d = 2.0 * M_PI * (a.L - r.L);
        Sum& sum = sums_[{static_cast<char>(s.sat.sys), a.band, a.attr, r.attr}];
        sum.c += std::cos(d);
        sum.s += std::sin(d);
        judgeable |= ++sum.n == kMinPairs;
      }
    }
  }
  return judgeable;
}

void PhaseAlignment::decide(const std::string& path) { judge(path, true); }

void PhaseAlignment::judge(const std::string& path, bool name_unrepaired) {
  // Each signal against the most preferred reference it was seen with.
  std::map<std::tuple<char, char, char>, char> ref_of;
  for (const auto& [key, sum] : sums_) {
    const auto [sys, band, attr, ref] = key;
    if (sum.n < kMinPairs || judged_.count({sys, band, attr})) continue;
    auto it = ref_of.find({sys, band, attr});
    if (it == ref_of.end() || attributeRank(ref) < attributeRank(it->second))
      ref_of[{sys, band, attr}] = ref;
  }
  for (const auto& [key, ref] : ref_of) {
    const auto [sys, band, attr] = key;
    judged_.insert(key);
    const Sum& sum = sums_.at({sys, band, attr, ref});
    SignalOffset o{sys, band, attr, ref};
    o.pairs = sum.n;
    o.cycles = std::atan2(sum.s, sum.c) / (2.0 * M_PI);
    o.consistency = std::hypot(sum.c, sum.s) / sum.n;
    const double quarter = std::round(4.0 * o.cycles) / 4.0;
    const std::string what = path + ": " + std::string(1, sys) + " L" + band + attr +
                             " phases sit " + cyclesText(o.cycles) + " cycles from L" + band + ref +
                             "'s on " + std::to_string(o.pairs) + " satellite-epochs tracking both";
    if (o.consistency < kMinConsistency) {
      // Too scattered to judge (signals not tracked coherently, as the 5.3 km base's L1Z against
      // its L1C): nothing is known to be wrong, so nothing is said or done.
    } else if (std::abs(o.cycles - quarter) > kQuarterTolerance) {
      if (name_unrepaired) warnings_.push_back(what + ", not a quarter cycle: left as they are");
    } else if (quarter != 0.0) {
      // RINEX 3.01 and later store phases aligned to the band's reference signal; this file's
      // are not. Aligned here as the standard's phase shift would have, and said.
      o.applied = quarter;
      shift_[{sys, band, attr}] = quarter;
      warnings_.push_back(what + ": aligned to L" + std::string(1, band) + ref + " by " +
                          cyclesText(-quarter) + " cycles (RINEX 3.01 phase alignment)");
    }
    offsets_.push_back(o);
  }
}

void PhaseAlignment::stream(ObsEpoch& e, const std::string& source) {
  if (add(e)) judge(source, false);
  if (shift_.empty()) return;
  apply(e);
  for (SatObs& s : e.sats) {
    for (SignalObs& g : s.signals) {
      const char sys = static_cast<char>(s.sat.sys);
      if (std::isnan(g.L) || !shift_.count({sys, g.band, g.attr})) continue;
      if (repaired_out_.insert({sys, s.sat.prn, g.band, g.attr}).second) g.lli |= 1;
    }
  }
}

void PhaseAlignment::apply(ObsEpoch& e) const {
  if (shift_.empty()) return;
  for (SatObs& s : e.sats) {
    for (SignalObs& g : s.signals) {
      const auto it = shift_.find({static_cast<char>(s.sat.sys), g.band, g.attr});
      if (it != shift_.end() && !std::isnan(g.L)) g.L -= it->second;
    }
  }
}

}  // namespace giocal
