#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "common/geodesy/wgs84.h"
#include "sim/simulator.h"
#include "temp_dir.h"

namespace giocal {
namespace {

TEST(Scenes, BlockageOutliersAndSlipsFollowTheSceneZones) {
  sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml");
  cfg.gnss.scenes = {sim::sceneDefaults("open_sky"), sim::sceneDefaults("more_trees"),
                     sim::sceneDefaults("building")};
  cfg.gnss.scenes[0].start = 0;
  cfg.gnss.scenes[0].end = 50;
  cfg.gnss.scenes[1].start = 50;
  cfg.gnss.scenes[1].end = 100;
  cfg.gnss.scenes[2].start = 100;
  cfg.gnss.scenes[2].end = 151;
  const sim::SimulatedLogs logs = sim::simulate(cfg, 3);
  double sats[3] = {0, 0, 0};
  int epochs[3] = {0, 0, 0}, lli[3] = {0, 0, 0};
  for (const ObsEpoch& e : logs.gnss.rover) {
    const int zone = std::min(2, static_cast<int>((e.t - logs.gnss.rover.front().t) / 50.0));
    sats[zone] += static_cast<double>(e.sats.size());
    ++epochs[zone];
    for (const auto& s : e.sats)
      for (const auto& sig : s.signals) lli[zone] += sig.lli & 1;
  }
  for (int z = 0; z < 3; ++z) sats[z] /= epochs[z];
  std::cout << "satellites per epoch: open sky " << sats[0] << ", more trees " << sats[1]
            << ", building " << sats[2] << "; slips " << logs.gnss.slips << "\n";
  EXPECT_GT(sats[0], sats[1] + 2.0);  // trees shadow low satellites
  EXPECT_GT(sats[0], sats[2] + 4.0);  // the building hides half of the sky below 60 deg
  EXPECT_EQ(lli[0], 0);               // no slips in open sky
  EXPECT_GT(logs.gnss.slips, 5);
  EXPECT_GT(lli[1] + lli[2], 0);  // about half of the slips are flagged
  // The base is in open sky: its satellite count stays that of the open-sky zone.
  double base_sats = 0;
  for (const ObsEpoch& e : logs.gnss.base) base_sats += static_cast<double>(e.sats.size());
  EXPECT_NEAR(base_sats / static_cast<double>(logs.gnss.base.size()), sats[0], 1.5);
  // The scenes in GPS time, cut to the drive (the last one is longer than it), for the report.
  ASSERT_EQ(logs.scenes.size(), 3u);
  const double t0 = logs.truth.front().t;
  EXPECT_DOUBLE_EQ(logs.scenes[1].t_start, t0 + 50.0);
  EXPECT_EQ(logs.scenes[2].type, "building");
  EXPECT_NEAR(logs.scenes[2].t_end, logs.truth.back().t, 0.02);
  test::TempDir dir;
  sim::writeDataset(logs, dir.path());
  std::ifstream csv(dir.file("scenes.csv"));
  std::string header, first;
  std::getline(csv, header);
  std::getline(csv, first);
  EXPECT_EQ(header, "t_start,t_end,type");
  EXPECT_EQ(first.substr(first.rfind(',') + 1), "open_sky");
}

TEST(Scenes, UnknownSceneTypeIsRejected) {
  EXPECT_THROW(sim::sceneDefaults("forest"), std::invalid_argument);
}

TEST(OdometerSlips, MeasuredSpeedIsHighDuringSlipEvents) {
  sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml");
  cfg.gnss.enabled = false;
  cfg.odometer.speed_sigma = 0.0;
  cfg.odometer.slip_rate_per_min = 10.0;
  cfg.odometer.slip_duration_s = 0.4;
  cfg.odometer.slip_speed_factor = 1.5;
  const sim::SimulatedLogs logs = sim::simulate(cfg, 9);
  int slipping = 0, moving = 0;
  for (size_t k = 0; k < logs.odom.size(); ++k) {
    if (logs.true_speed[k] < 0.2) continue;
    ++moving;
    const double ratio = logs.odom[k].v * (1 + cfg.truth.s_v) / logs.true_speed[k];
    if (std::abs(ratio - 1.5) < 1e-9)
      ++slipping;
    else
      EXPECT_NEAR(ratio, 1.0, 1e-9);
  }
  // 10 events per minute of 0.4 s: about 7 % of the driving samples.
  EXPECT_GT(slipping, moving / 50);
  EXPECT_LT(slipping, moving / 5);
}

}  // namespace
}  // namespace giocal
