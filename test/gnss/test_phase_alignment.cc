// The alignment check of one receiver's phase signals of a band (RINEX 3.01 and later store them
// aligned): a signal a quarter or half cycle off is aligned with a warning, one off by something
// else is named and left, one too scattered to judge is left, and the real files in data/; the
// same on a stream.
#include <gtest/gtest.h>

#include <iostream>
#include <random>

#include "common/gnss/phase_alignment.h"
#include "common/gnss/rinex_obs.h"

namespace giocal {
namespace {

// Epochs of GPS satellites tracking L2W and L2X, L2X `offset` cycles from L2W plus noise of
// `noise` cycles; every signal on its own integer.
std::vector<ObsEpoch> twoSignals(double offset, double noise, int epochs) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n(0.0, noise);
  std::uniform_int_distribution<int> integer(-1000, 1000);
  std::vector<ObsEpoch> out;
  for (int k = 0; k < epochs; ++k) {
    ObsEpoch e;
    e.t = k;
    for (int prn = 1; prn <= 4; ++prn) {
      SatObs s;
      s.sat = {GnssSystem::kGps, prn};
      const double phase = 1e6 * prn + 100.3 * k;
      s.signals.push_back({'2', 'W', 2e7, phase + 17 * prn});
      s.signals.push_back({'2', 'X', 2e7, phase - 5 * prn + offset + n(rng)});
      s.signals.push_back({'1', 'C', 2e7, phase + integer(rng)});
      e.sats.push_back(s);
    }
    out.push_back(e);
  }
  return out;
}

PhaseAlignment checked(const std::vector<ObsEpoch>& epochs) {
  PhaseAlignment a;
  for (const ObsEpoch& e : epochs) a.add(e);
  a.decide("f.obs");
  return a;
}

TEST(PhaseAlignment, AQuarterOrHalfCycleOffIsAlignedWithAWarning) {
  for (const double offset : {0.25, -0.25, 0.5, -0.5}) {
    SCOPED_TRACE(offset);
    std::vector<ObsEpoch> epochs = twoSignals(offset, 0.01, 30);
    const PhaseAlignment a = checked(epochs);
    ASSERT_EQ(a.offsets().size(), 1u);
    const SignalOffset& o = a.offsets().front();
    EXPECT_EQ(o.attr, 'X');
    EXPECT_EQ(o.ref, 'W');
    EXPECT_EQ(o.pairs, 120);
    EXPECT_NEAR(std::abs(o.applied), std::abs(offset), 1e-12);
    ASSERT_EQ(a.warnings().size(), 1u);
    EXPECT_NE(a.warnings().front().find("f.obs: G L2X phases sit"), std::string::npos);
    // Aligned: L2X minus L2W is a whole number of cycles plus the noise.
    for (ObsEpoch& e : epochs) {
      a.apply(e);
      const double d = e.sats[0].signals[1].L - e.sats[0].signals[0].L;
      EXPECT_NEAR(d - std::round(d), 0.0, 0.06);
    }
  }
}

TEST(PhaseAlignment, AlignedScatteredOrOddOffsetsAreLeftAsTheyAre) {
  const PhaseAlignment aligned = checked(twoSignals(0.0, 0.01, 30));
  ASSERT_EQ(aligned.offsets().size(), 1u);
  EXPECT_EQ(aligned.offsets().front().applied, 0.0);
  EXPECT_TRUE(aligned.warnings().empty());
  const PhaseAlignment odd = checked(twoSignals(0.13, 0.01, 30));
  EXPECT_EQ(odd.offsets().front().applied, 0.0);
  ASSERT_EQ(odd.warnings().size(), 1u);
  EXPECT_NE(odd.warnings().front().find("not a quarter cycle"), std::string::npos);
  const PhaseAlignment scattered = checked(twoSignals(0.25, 0.3, 30));
  EXPECT_EQ(scattered.offsets().front().applied, 0.0);
  EXPECT_LT(scattered.offsets().front().consistency, PhaseAlignment::kMinConsistency);
  EXPECT_TRUE(scattered.warnings().empty());
  // Too few satellite-epochs with both signals: not judged.
  EXPECT_TRUE(checked(twoSignals(0.25, 0.01, 4)).offsets().empty());
}

// The same check on a stream of epochs (the live Calibrator): a signal is judged once its pairs
// reach kMinPairs and repaired from that epoch on, its first repaired phase marked a loss of lock.
TEST(PhaseAlignment, AStreamIsRepairedFromItsJudgmentOnAndItsAmbiguitiesRestart) {
  const std::vector<ObsEpoch> raw = twoSignals(0.25, 0.01, 10);
  PhaseAlignment stream;
  // Four pairs an epoch: the fifth epoch brings the 20th, and the judgment.
  for (size_t k = 0; k < raw.size(); ++k) {
    SCOPED_TRACE(k);
    ObsEpoch e = raw[k];
    stream.stream(e, "the base's epochs");
    for (size_t i = 0; i < e.sats.size(); ++i) {
      const SignalObs &w = e.sats[i].signals[0], &x = e.sats[i].signals[1];
      const SignalObs& x_raw = raw[k].sats[i].signals[1];
      EXPECT_EQ(w.L, raw[k].sats[i].signals[0].L);  // the reference is never touched
      EXPECT_EQ(w.lli, 0);
      if (k < 4) {
        EXPECT_EQ(x.L, x_raw.L);  // before the judgment: as they came
        EXPECT_EQ(x.lli, 0);
      } else {
        EXPECT_NEAR(x.L, x_raw.L - 0.25, 1e-6);
        EXPECT_EQ(x.lli, k == 4 ? 1 : 0);  // the first repaired phase: a new ambiguity
      }
    }
  }
  ASSERT_EQ(stream.warnings().size(), 1u);
  EXPECT_NE(stream.warnings()[0].find("the base's epochs: G L2X phases sit +0.25 cycles from L2W"),
            std::string::npos)
      << stream.warnings()[0];
  // Aligned phases, or an offset that is not a quarter cycle, go through untouched and unnamed.
  for (const double offset : {0.0, 0.13}) {
    PhaseAlignment quiet;
    for (const ObsEpoch& r : twoSignals(offset, 0.01, 10)) {
      ObsEpoch e = r;
      quiet.stream(e, "rover");
      for (size_t i = 0; i < e.sats.size(); ++i) {
        EXPECT_EQ(e.sats[i].signals[1].L, r.sats[i].signals[1].L);
        EXPECT_EQ(e.sats[i].signals[1].lli, 0);
      }
    }
    EXPECT_TRUE(quiet.warnings().empty()) << offset;
  }
}

// Every real file in data/ with two phase signals on a band. The Septentrio files (mosaic pair,
// the 5.3 km rover) are aligned. The 5.3 km pair's Trimble NetR9 base is not: its L2X sits a
// quarter cycle from its L2W and its QZSS L1X from its L1C, by the very corrections its header
// records as applied (G L2X -0.25, J L1X +0.25); both are aligned and named.
TEST(PhaseAlignment, TheRealFilesAreAlignedOrRepairedWhereTheyAreNot) {
  const std::string d = std::string(GIOCAL_SOURCE_DIR) + "/data/real/";
  const std::string trimble = "cssrlib-static-5km/3034078M1.21O";
  int judged = 0;
  for (const std::string f : {"mosaic-static-nagoya/rover.obs", "mosaic-static-nagoya/base.obs",
                              "cssrlib-static-5km/SEPT078M1.21O", trimble.c_str()}) {
    const RinexObsReader reader(d + f);
    for (const SignalOffset& o : reader.phaseOffsets()) {
      std::cout << f << ": " << o.sys << " L" << o.band << o.attr << " - L" << o.band << o.ref
                << " " << o.cycles << " cycles, consistency " << o.consistency << ", " << o.pairs
                << " pairs, aligned by " << -o.applied << "\n";
      double expected = 0.0;
      if (f == trimble && o.sys == 'G' && o.band == '2' && o.attr == 'X') expected = -0.25;
      if (f == trimble && o.sys == 'J' && o.band == '1' && o.attr == 'X') expected = 0.25;
      EXPECT_EQ(o.applied, expected) << f << " " << o.sys << o.band << o.attr;
      ++judged;
    }
    EXPECT_EQ(reader.warnings().size(), f == trimble ? 2u : 0u) << f;
  }
  EXPECT_EQ(judged, 6);
}

}  // namespace
}  // namespace giocal
