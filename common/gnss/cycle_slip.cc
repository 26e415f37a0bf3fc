#include "common/gnss/cycle_slip.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>
#include <vector>

#include "common/math/median.h"
#include "common/math/sorted_by_key.h"

namespace giocal {

namespace {

// Geometry-free [m] and Melbourne-Wuebbena [wide-lane cycles] combinations of two signals.
bool combinations(GnssSystem sys, const SignalObs* a, const SignalObs* b, double& gf, double& mw) {
  if (!a || !b || std::isnan(a->L) || std::isnan(b->L)) return false;
  const double fa = carrierFrequency(sys, a->band), fb = carrierFrequency(sys, b->band);
  if (fa <= 0.0 || fb <= 0.0 || fa == fb) return false;
  gf = kSpeedOfLight / fa * a->L - kSpeedOfLight / fb * b->L;
  const double lw = kSpeedOfLight / (fa - fb);
  mw = (a->L - b->L) - (fa * a->P + fb * b->P) / (fa + fb) / lw;
  return true;
}

double medianOf(const std::vector<std::pair<std::pair<SatId, char>, double>>& values) {
  std::vector<double> v;
  v.reserve(values.size());
  for (const auto& m : values) v.push_back(m.second);
  return median(v);
}

}  // namespace

void CycleSlipDetector::update(const ObsEpoch& epoch) {
  slip_.clear();
  // Doppler check: the phase change against the Doppler prediction, with the part common to all
  // satellites (receiver clock jumps) removed by the median.
  std::vector<std::pair<Key, double>> doppler_misfit;
  // Melbourne-Wuebbena jumps, tested after the part common to all satellites is removed: a
  // receiver that steps the clock of its code alone (by a millisecond) moves every one alike.
  // In metres: the common part is the same for every wide-lane wavelength.
  std::vector<std::pair<Key, double>> mw_jumps;
  std::vector<double> mw_widelanes;
  next_.clear();
  for (const SatObs& so : epoch.sats) {
    const SignalObs* prim = so.bestOnBand(primaryBand(so.sat.sys));
    // The bands with a phase, in order of first appearance (a fixed array: a vector here was an
    // allocation per satellite and epoch).
    std::array<char, 16> band_list{};
    std::size_t nb = 0;
    for (const SignalObs& s : so.signals) {
      if (!std::isnan(s.L) && nb < band_list.size() &&
          std::find(band_list.begin(), band_list.begin() + nb, s.band) == band_list.begin() + nb) {
        band_list[nb++] = s.band;
      }
    }
    const auto bands = std::basic_string_view<char>(band_list.data(), nb);
    for (char band : bands) {
      const SignalObs* s = so.bestOnBand(band);
      if (!s || std::isnan(s->L)) continue;
      // Pair with the primary band, or (for the primary band) with the first other band.
      const SignalObs* other = nullptr;
      if (s != prim) {
        other = prim;
      } else {
        for (char b2 : bands) {
          if (b2 != band && !other) other = so.bestOnBand(b2);
        }
      }
      double gf = 0.0, mw = 0.0;
      const bool dual = combinations(so.sat.sys, s, other, gf, mw);
      const auto key = std::make_pair(so.sat, band);
      Track tr;
      tr.t = epoch.t;
      tr.L = s->L;
      tr.D = s->D;
      tr.gf = gf;
      tr.mw = mw;
      tr.has_gf = dual;
      tr.has_mw = dual && !std::isnan(mw);
      tr.attr = s->attr;
      tr.partner_attr = dual ? other->attr : 0;
      bool slip = (s->lli & 1) != 0 || epoch.flag == 1;
      const auto it = findKey(tracks_, key);
      // Another signal of the band (L2W after L2L) is another tracking loop: its phase has its
      // own integer, and in files whose phases are not aligned (RINEX 2, 3.00) a quarter cycle.
      if (it == tracks_.end() || epoch.t - it->second.t > options_.max_gap ||
          it->second.attr != tr.attr) {
        slip = true;
      } else {
        const Track& p = it->second;
        const double dt = epoch.t - p.t;
        // The combinations compare across epochs only with the same partner signal.
        const bool same_partner = p.partner_attr == tr.partner_attr;
        const bool gf_tested = dual && p.has_gf && same_partner;
        if (gf_tested && std::abs(gf - p.gf) > options_.gf_threshold + options_.gf_rate * dt) {
          slip = true;
        }
        // The trapezoidal Doppler prediction holds over a short gap only; over a longer one
        // without the geometry-free test nothing can tell a slip, so it counts as one.
        const bool doppler_tested =
            dt <= options_.doppler_max_gap && !std::isnan(s->D) && !std::isnan(p.D);
        if (dt > options_.doppler_max_gap) {
          if (!gf_tested) slip = true;
        } else if (doppler_tested) {
          doppler_misfit.push_back({key, (s->L - p.L) + 0.5 * (s->D + p.D) * dt});
        }
        // Melbourne-Wuebbena carries the code: an NLOS or multipath code error of metres moves it
        // by as many wide-lane cycles. When the phase alone passes both the geometry-free and the
        // Doppler test, its jump is the code's, not a slip (the code outlier check deals with
        // it); it decides only where one of those tests is missing.
        if (tr.has_mw && p.has_mw && same_partner && !(gf_tested && doppler_tested)) {
          // Signed: a pair taken in either order then moves by the same metres.
          const double lw = kSpeedOfLight / (carrierFrequency(so.sat.sys, s->band) -
                                             carrierFrequency(so.sat.sys, other->band));
          mw_jumps.push_back({key, (mw - p.mw) * lw});
          mw_widelanes.push_back(lw);
        }
      }
      slip_.push_back({key, slip});
      next_.push_back({key, tr});
    }
  }
  std::sort(slip_.begin(), slip_.end(), ByKey());
  const double mw_common = mw_jumps.size() >= 3 ? medianOf(mw_jumps) : 0.0;
  for (size_t k = 0; k < mw_jumps.size(); ++k) {
    if (std::abs(mw_jumps[k].second - mw_common) >
        options_.mw_threshold * std::abs(mw_widelanes[k]))
      findKey(slip_, mw_jumps[k].first)->second = true;
  }
  if (doppler_misfit.size() >= 3) {
    const double common = medianOf(doppler_misfit);
    for (const auto& m : doppler_misfit) {
      if (std::abs(m.second - common) > options_.doppler_threshold) {
        findKey(slip_, m.first)->second = true;
      }
    }
  }
  // Tracks of signals not seen this epoch are kept until max_gap, so that a signal blocked for a
  // moment is tested against its last value instead of counting as new.
  std::sort(next_.begin(), next_.end(), ByKey());
  const auto seen = static_cast<std::ptrdiff_t>(next_.size());
  for (const auto& [key, tr] : tracks_) {
    if (epoch.t - tr.t <= options_.max_gap &&
        !std::binary_search(next_.begin(), next_.begin() + seen, std::pair<Key, Track>{key, tr},
                            ByKey())) {
      next_.push_back({key, tr});
    }
  }
  std::inplace_merge(next_.begin(), next_.begin() + seen, next_.end(), ByKey());
  std::swap(tracks_, next_);
}

bool CycleSlipDetector::slipped(const SatId& sat, char band) const {
  const auto it = findKey(slip_, Key{sat, band});
  return it == slip_.end() || it->second;
}

}  // namespace giocal
