#include <gtest/gtest.h>

#include <random>

#include "common/gnss/code_outlier_check.h"

namespace giocal {
namespace {

/// Eight GPS satellites whose ranges change at constant rates, with code noise, a receiver clock
/// that jumps by a millisecond (all pseudo-ranges alike) and one NLOS error.
TEST(CodeOutlierCheck, FlagsAJumpAgainstDopplerButNotAClockJump) {
  CodeOutlierCheck check;
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 0.3);
  const double lambda = kSpeedOfLight / carrierFrequency(GnssSystem::kGps, '1');
  int flagged_good = 0, flagged_bad = 0;
  for (int k = 0; k < 60; ++k) {
    ObsEpoch e;
    e.t = 1000.0 + k;
    const double clock = k >= 30 ? 299792.458 : 0.0;  // 1 ms jump at epoch 30
    for (int s = 0; s < 8; ++s) {
      SatObs so;
      so.sat = SatId{GnssSystem::kGps, s + 1};
      const double rate = -300.0 + 100.0 * s;  // range rate [m/s]
      SignalObs sig;
      sig.band = '1';
      sig.P = 2.2e7 + rate * k + clock + noise(rng);
      sig.D = -rate / lambda;
      const bool nlos = s == 3 && k == 40;
      if (nlos) sig.P += 8.0;
      so.signals.push_back(sig);
      e.sats.push_back(so);
    }
    const auto out = check.check(e);
    for (const auto& key : out) {
      if (key.first.prn == 4 && k == 40) {
        ++flagged_bad;
      } else {
        ++flagged_good;
      }
    }
  }
  EXPECT_EQ(flagged_bad, 1);
  EXPECT_EQ(flagged_good, 0) << "noise or the common clock jump were flagged";
}

TEST(CodeOutlierCheck, ATrueStepIsAcceptedAfterAFewEpochs) {
  // A persistent change (for example a new code bias) is not rejected forever.
  CodeOutlierCheck check;
  const double lambda = kSpeedOfLight / carrierFrequency(GnssSystem::kGps, '1');
  int flagged = 0;
  for (int k = 0; k < 20; ++k) {
    ObsEpoch e;
    e.t = k;
    for (int s = 0; s < 6; ++s) {
      SatObs so;
      so.sat = SatId{GnssSystem::kGps, s + 1};
      SignalObs sig;
      sig.P = 2.1e7 + 50.0 * s * k + (s == 0 && k >= 10 ? 20.0 : 0.0);
      sig.D = -50.0 * s / lambda;
      so.signals.push_back(sig);
      e.sats.push_back(so);
    }
    flagged += static_cast<int>(check.check(e).size());
  }
  EXPECT_GE(flagged, 1);
  EXPECT_LE(flagged, CodeOutlierOptions().max_consecutive);
}

TEST(CodeOutlierCheck, TheFirstSignalOfABandCountsAndATrackOutlivesAMissedEpoch) {
  // Satellites listed in falling PRN order, three of them with a second signal on L1 whose code
  // drifts by 50 m per epoch: only the first listed signal of a band is checked. Satellite 2
  // misses epoch 5 and comes back with a 10 m jump, which its kept track sees.
  CodeOutlierCheck check;
  const double lambda = kSpeedOfLight / carrierFrequency(GnssSystem::kGps, '1');
  std::vector<std::pair<int, int>> flagged;  // (epoch, prn)
  for (int k = 0; k < 8; ++k) {
    ObsEpoch e;
    e.t = k;
    for (int s = 7; s >= 0; --s) {
      if (s == 1 && k == 5) continue;
      SatObs so;
      so.sat = SatId{GnssSystem::kGps, s + 1};
      SignalObs sig;
      sig.P = 2.1e7 + 40.0 * s * k + (s == 1 && k == 6 ? 10.0 : 0.0);
      sig.D = -40.0 * s / lambda;
      so.signals.push_back(sig);
      sig.P += 50.0 * k;  // a second, bad tracking of the same band
      if (s % 3 == 0) so.signals.push_back(sig);
      e.sats.push_back(so);
    }
    for (const auto& key : check.check(e)) flagged.push_back({k, key.first.prn});
  }
  EXPECT_EQ(flagged, (std::vector<std::pair<int, int>>{{6, 2}}));
}

}  // namespace
}  // namespace giocal
