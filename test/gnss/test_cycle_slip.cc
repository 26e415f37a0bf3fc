#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "common/gnss/cycle_slip.h"
#include "common/gnss/rinex_obs.h"
#include "temp_dir.h"

namespace giocal {
namespace {

const std::string kMosaic = std::string(GIOCAL_SOURCE_DIR) + "/data/real/mosaic-static-nagoya/";

SignalObs* signal(ObsEpoch& e, const SatId& sat, char band) {
  for (auto& s : e.sats) {
    if (s.sat != sat) continue;
    for (auto& sig : s.signals) {
      if (sig.band == band && !std::isnan(sig.L)) return &sig;
    }
  }
  return nullptr;
}

TEST(CycleSlip, FewFalseAlarmsOnRealDataAndInjectedSlipsAreFound) {
  ObsData d = readRinexObs(kMosaic + "rover.obs");
  const SatId g{GnssSystem::kGps, 13};
  ASSERT_NE(signal(d.epochs[150], g, '1'), nullptr);
  ASSERT_NE(signal(d.epochs[150], g, '2'), nullptr);
  // Clean data: count slips flagged after each signal's first epoch.
  {
    CycleSlipDetector det;
    int flagged = 0, total = 0;
    for (size_t k = 0; k < d.epochs.size(); ++k) {
      det.update(d.epochs[k]);
      if (k == 0) continue;
      for (const auto& s : d.epochs[k].sats) {
        for (const auto& sig : s.signals) {
          if (std::isnan(sig.L)) continue;
          ++total;
          flagged += det.slipped(s.sat, sig.band);
        }
      }
    }
    std::cout << "clean mosaic rover: " << flagged << " of " << total
              << " phase observations flagged\n";
    EXPECT_LT(flagged, total / 200);  // < 0.5 %, mostly satellites rising into view
  }
  // Injected: +1 cycle on L1 from epoch 150, +7 cycles on L2 from 200, both for G13.
  for (size_t k = 150; k < d.epochs.size(); ++k) signal(d.epochs[k], g, '1')->L += 1.0;
  for (size_t k = 200; k < d.epochs.size(); ++k) signal(d.epochs[k], g, '2')->L += 7.0;
  // A loss-of-lock flag on L1 at epoch 250.
  signal(d.epochs[250], g, '1')->lli |= 1;
  CycleSlipDetector det;
  std::vector<size_t> slips_l1, slips_l2;
  for (size_t k = 0; k < d.epochs.size(); ++k) {
    det.update(d.epochs[k]);
    if (k > 0 && det.slipped(g, '1')) slips_l1.push_back(k);
    if (k > 0 && det.slipped(g, '2')) slips_l2.push_back(k);
  }
  EXPECT_NE(std::find(slips_l1.begin(), slips_l1.end(), 150u), slips_l1.end());
  EXPECT_NE(std::find(slips_l1.begin(), slips_l1.end(), 250u), slips_l1.end());
  EXPECT_NE(std::find(slips_l2.begin(), slips_l2.end(), 200u), slips_l2.end());
  EXPECT_EQ(std::find(slips_l1.begin(), slips_l1.end(), 151u), slips_l1.end()) << "only once";
  EXPECT_LE(slips_l1.size(), 4u);
}

void removeSatellite(ObsEpoch& e, const SatId& sat) {
  e.sats.erase(
      std::remove_if(e.sats.begin(), e.sats.end(), [&](const SatObs& s) { return s.sat == sat; }),
      e.sats.end());
}

void removeBand(ObsEpoch& e, char band) {
  for (auto& s : e.sats) {
    s.signals.erase(std::remove_if(s.signals.begin(), s.signals.end(),
                                   [&](const SignalObs& o) { return o.band == band; }),
                    s.signals.end());
  }
}

// A satellite blocked for a few epochs (trees) comes back on the same ambiguity: it is tested
// against its last value instead of counting as new, and a slip during the gap is still found.
TEST(CycleSlip, ASignalBlockedForAMomentIsTestedAcrossTheGap) {
  ObsData d = readRinexObs(kMosaic + "rover.obs");
  const SatId g{GnssSystem::kGps, 13};
  ASSERT_GT(d.epochs[103].t - d.epochs[99].t, 3.5);
  for (size_t k = 100; k < 103; ++k) removeSatellite(d.epochs[k], g);
  for (size_t k = 200; k < 203; ++k) removeSatellite(d.epochs[k], g);
  for (size_t k = 203; k < d.epochs.size(); ++k) signal(d.epochs[k], g, '1')->L += 1.0;
  CycleSlipDetector det;
  for (size_t k = 0; k <= 203; ++k) {
    det.update(d.epochs[k]);
    if (k == 103) {
      EXPECT_FALSE(det.slipped(g, '1')) << "clean return after a 3-epoch gap";
      EXPECT_FALSE(det.slipped(g, '2'));
    }
  }
  EXPECT_TRUE(det.slipped(g, '1')) << "one cycle on L1 during the gap (geometry-free test)";

  // Single frequency: no geometry-free test, so a gap longer than the Doppler test can bridge
  // counts as a slip, and a short one is bridged by the Doppler test.
  ObsData s = readRinexObs(kMosaic + "rover.obs");
  for (auto& e : s.epochs) removeBand(e, '2');
  removeSatellite(s.epochs[100], g);
  for (size_t k = 200; k < 205; ++k) removeSatellite(s.epochs[k], g);
  CycleSlipDetector single;
  for (size_t k = 0; k <= 205; ++k) {
    single.update(s.epochs[k]);
    if (k == 101) {
      EXPECT_FALSE(single.slipped(g, '1')) << "one missing epoch, Doppler bridges it";
    }
  }
  EXPECT_TRUE(single.slipped(g, '1')) << "5 s without a geometry-free test";
}

// The mosaic rover tracks GPS L2 twice (L2W and L2L). When L2W drops out, L2L is another tracking
// loop with its own integer (and, in files whose phases are not aligned, a quarter cycle): the
// band counts as slipped. L1's geometry-free partner changed with it, so L1 is tested by its
// Doppler alone and stays continuous.
TEST(CycleSlip, AnotherSignalOnTheBandIsANewAmbiguity) {
  ObsData d = readRinexObs(kMosaic + "rover.obs");
  const SatId g{GnssSystem::kGps, 5};
  const auto drop_w = [&](ObsEpoch& e) {
    for (auto& so : e.sats) {
      if (so.sat != g) continue;
      so.signals.erase(
          std::remove_if(so.signals.begin(), so.signals.end(),
                         [](const SignalObs& x) { return x.band == '2' && x.attr == 'W'; }),
          so.signals.end());
    }
  };
  const auto best_l2 = [&](const ObsEpoch& e) {
    const SignalObs* s = nullptr;
    for (const auto& so : e.sats) {
      if (so.sat == g) s = so.bestOnBand('2');
    }
    return s ? s->attr : '-';
  };
  ASSERT_EQ(best_l2(d.epochs[150]), 'W');
  for (size_t k = 150; k < d.epochs.size(); ++k) drop_w(d.epochs[k]);
  ASSERT_EQ(best_l2(d.epochs[150]), 'L');
  ASSERT_EQ(best_l2(d.epochs[151]), 'L');
  CycleSlipDetector det;
  for (size_t k = 0; k <= 151; ++k) {
    det.update(d.epochs[k]);
    if (k == 149) {
      EXPECT_FALSE(det.slipped(g, '2'));
    }
    if (k == 150) {
      EXPECT_TRUE(det.slipped(g, '2')) << "L2W -> L2L";
      EXPECT_FALSE(det.slipped(g, '1')) << "L1 continuous, its partner changed";
    }
    if (k == 151) {
      EXPECT_FALSE(det.slipped(g, '2')) << "L2L continuous from then on";
    }
  }
}

// An NLOS code error of 20 m on both bands moves Melbourne-Wuebbena by about 23 wide-lane cycles
// while the phases stay continuous: with the geometry-free and Doppler tests passing it is not a
// slip (10 % NLOS code used to restart ambiguities about 1650 times in 150 s); without Doppler the
// Melbourne-Wuebbena test still decides.
TEST(CycleSlip, ACodeOutlierIsNotASlipWhenThePhaseTestsPass) {
  const SatId g{GnssSystem::kGps, 13};
  for (const bool with_doppler : {true, false}) {
    ObsData d = readRinexObs(kMosaic + "rover.obs");
    for (auto& e : d.epochs) {
      for (auto& so : e.sats) {
        for (auto& sig : so.signals) {
          if (!with_doppler) sig.D = NAN;
        }
      }
    }
    for (char band : {'1', '2'}) signal(d.epochs[150], g, band)->P += 20.0;
    CycleSlipDetector det;
    for (size_t k = 0; k <= 150; ++k) det.update(d.epochs[k]);
    EXPECT_EQ(det.slipped(g, '1'), !with_doppler)
        << (with_doppler ? "with" : "without") << " Doppler";
  }
}

TEST(RinexObs, EventFlagRecordsAreSkipped) {
  std::ifstream in(kMosaic + "rover.obs");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  // Insert "new site occupation" (flag 3, two header lines) and an external event (flag 5) before
  // the second epoch record.
  const size_t second = text.find("\n>", text.find("END OF HEADER") + 200) + 1;
  const std::string special =
      ">                              3  2\n"
      "NEW SITE                                                    MARKER NAME         \n"
      "        0.0000        0.0000        0.0000                  ANTENNA: DELTA H/E/N\n"
      "> 2024 06 24 08 20 00.5000000  5  0\n";
  text.insert(second, special);
  test::TempDir dir;
  const ObsData d = readRinexObs(dir.write("events.obs", text));
  EXPECT_EQ(d.epochs.size(), 301u);
  EXPECT_EQ(d.skipped_special_records, 2);
}

}  // namespace
}  // namespace giocal
