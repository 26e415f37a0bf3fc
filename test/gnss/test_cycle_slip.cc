#include <gtest/gtest.h>

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
