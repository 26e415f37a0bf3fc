// IonosphereRate: the ionosphere's change taken out of a single receiver's time-differenced phase
// from each satellite's geometry-free phase.
#include <gtest/gtest.h>

#include "common/gnss/ionosphere_rate.h"
#include "common/gnss/observation.h"
#include "common/gnss/time_differenced_phase.h"

namespace giocal {
namespace {

// Satellites whose first-band delay grows by rates[i] metres a second, seen on two bands,
// between t and t + 1 s: each phase change is the range change minus the delay's change on its
// band.
TdcpPair pairAt(double t, const std::vector<SatId>& sats, const std::vector<double>& rates,
                bool second_band_of_first = true) {
  TdcpPair pair;
  pair.t0 = t;
  pair.t1 = t + 1.0;
  for (size_t i = 0; i < sats.size(); ++i) {
    const double lambda1 = kSpeedOfLight / carrierFrequency(sats[i].sys, primaryBand(sats[i].sys));
    for (char band : ddBands(sats[i].sys, 2)) {
      if (i == 0 && band != primaryBand(sats[i].sys) && !second_band_of_first) continue;
      TdcpSignal g;
      g.sat = sats[i];
      g.band = band;
      g.lambda = kSpeedOfLight / carrierFrequency(sats[i].sys, band);
      const double range_change = 0.1 * sats[i].prn;
      g.phase_change_m = range_change - rates[i] * (g.lambda / lambda1) * (g.lambda / lambda1);
      g.variance = 2.0 * 0.003 * 0.003;
      pair.signals.push_back(g);
    }
  }
  return pair;
}

TEST(IonosphereRate, TheDelaysChangeIsTakenOutOfBothBandsOnceItsSpanIsLongEnough) {
  // Each satellite's range changes by 0.1 m times its PRN; GPS L1/L2 and Galileo E1/E5a.
  const std::vector<SatId> sats{
      {GnssSystem::kGps, 1}, {GnssSystem::kGps, 2}, {GnssSystem::kGalileo, 3}};
  const std::vector<double> rates{5e-4, -3e-4, 1e-3};  // [m/s] on the first band
  IonosphereRate ionosphere(120.0, 10.0);
  for (int k = 0; k < 200; ++k) {
    TdcpPair pair = pairAt(100.0 + k, sats, rates, k != 50);
    const TdcpPair raw = pair;
    const int corrected = ionosphere.correct(pair);
    // The first satellite's track starts at 0 and again after the pair without its second band
    // (k = 50); the others' at 0 only.
    const bool first_ready = (k >= 9 && k < 50) || k >= 60;
    EXPECT_EQ(corrected, (first_ready ? 2 : 0) + (k >= 9 ? 4 : 0)) << "pair " << k;
    for (size_t i = 0; i < pair.signals.size(); ++i) {
      const TdcpSignal& g = pair.signals[i];
      const bool ready = g.sat.prn == 1 ? first_ready : k >= 9;
      if (ready) {
        EXPECT_NEAR(g.phase_change_m, 0.1 * g.sat.prn, 1e-9) << "pair " << k;
        EXPECT_GT(g.variance, raw.signals[i].variance);
        // A rate fitted over ten seconds or more adds little to a time difference's noise.
        EXPECT_LT(g.variance, 1.2 * raw.signals[i].variance);
      } else {
        EXPECT_EQ(g.phase_change_m, raw.signals[i].phase_change_m) << "pair " << k;
        EXPECT_EQ(g.variance, raw.signals[i].variance);
      }
    }
  }
}

TEST(IonosphereRate, AThirdBandIsCorrectedAndAWindowShorterThanTheSpanStillGivesARate) {
  // GPS L1, L2 and L5: the delay on each band is (f_1/f)^2 times L1's.
  const SatId g1{GnssSystem::kGps, 1}, g2{GnssSystem::kGps, 2};
  IonosphereRate short_window(20.0, 60.0);
  for (int k = 0; k < 30; ++k) {
    TdcpPair pair;
    pair.t0 = 100.0 + k;
    pair.t1 = pair.t0 + 1.0;
    for (const SatId& sat : {g1, g2}) {
      const double lambda1 = kSpeedOfLight / carrierFrequency(sat.sys, '1');
      for (char band : ddBands(sat.sys, 3)) {
        TdcpSignal g;
        g.sat = sat;
        g.band = band;
        g.lambda = kSpeedOfLight / carrierFrequency(sat.sys, band);
        const double ratio = (g.lambda / lambda1) * (g.lambda / lambda1);
        g.phase_change_m = 0.1 * sat.prn - 4e-4 * ratio;
        g.variance = 2.0 * 0.003 * 0.003;
        pair.signals.push_back(g);
      }
    }
    ASSERT_EQ(pair.signals.size(), 6u);
    EXPECT_EQ(short_window.correct(pair), k >= 19 ? 6 : 0) << "pair " << k;
    if (k < 19) continue;
    for (const TdcpSignal& g : pair.signals) EXPECT_NEAR(g.phase_change_m, 0.1 * g.sat.prn, 1e-9);
  }
}

TEST(IonosphereRate, AStepAcrossAGapOrAWindowOfZeroCorrectsNothing) {
  const std::vector<SatId> sats{{GnssSystem::kGps, 1}, {GnssSystem::kGps, 2}};
  IonosphereRate off(0.0, 10.0);
  IonosphereRate gapped(120.0, 10.0);
  for (int k = 0; k < 30; ++k) {
    TdcpPair pair = pairAt(100.0 + k, sats, {5e-4, 5e-4});
    EXPECT_EQ(off.correct(pair), 0);
  }
  for (int k = 0; k < 30; ++k) {
    // Every tenth pair starts two seconds after the last one ended: the tracks start again.
    TdcpPair pair = pairAt(100.0 + k + 2.0 * (k / 10), sats, {5e-4, 5e-4});
    EXPECT_EQ(gapped.correct(pair), k % 10 == 9 ? 4 : 0) << "pair " << k;
  }
}

}  // namespace
}  // namespace giocal
