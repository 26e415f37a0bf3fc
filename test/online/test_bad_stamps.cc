// One glitched stamp in a log (a GPS week rollover on one odometer row) costs that row only.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "replay/replay.h"
#include "sim/simulator.h"
#include "temp_dir.h"

namespace giocal {
namespace {

std::vector<std::string> lines(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

void write(const std::string& path, const std::vector<std::string>& rows) {
  std::ofstream out(path);
  for (const std::string& l : rows) out << l << '\n';
}

// The row 1024 weeks late calibrates exactly as the log without that row, and one warning names
// its line; before, the reader stopped at "101 rows in a row ... going backwards".
TEST(BadStamps, OneOdometerRowAWeekRolloverAheadCostsThatRowOnly) {
  test::TempDir dir;
  const sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml");
  const sim::SimulatedLogs data = sim::simulate(cfg, 15);
  sim::writeDataset(data, dir.file("glitch"));
  sim::writeDataset(data, dir.file("without"));
  std::vector<std::string> odom = lines(dir.file("glitch") + "/odom.csv");
  ASSERT_GT(odom.size(), 2102u);
  const std::string row = odom[2101];  // line 2102
  std::istringstream fields(row);
  double t = 0.0;
  fields >> t;
  const std::string rest = row.substr(row.find(','));
  std::ostringstream glitched;
  glitched.precision(17);
  glitched << t + 1024 * 604800.0 << rest;
  odom[2101] = glitched.str();
  write(dir.file("glitch") + "/odom.csv", odom);
  odom.erase(odom.begin() + 2101);
  write(dir.file("without") + "/odom.csv", odom);

  ReplayJob job;
  job.estimator = "ekf";
  const CalibrationRun a = replayFolder(dir.file("glitch"), job, nullptr);
  const CalibrationRun b = replayFolder(dir.file("without"), job, nullptr);
  EXPECT_EQ(a.final().calib.p_b_m, b.final().calib.p_b_m);
  EXPECT_EQ(a.final().calib.s_v, b.final().calib.s_v);
  EXPECT_EQ(a.final().cov, b.final().cov);
  int named = 0;
  for (const std::string& w : a.warnings)
    named += w.find("odom.csv:2102: 1 rows stamped far ahead") != std::string::npos;
  EXPECT_EQ(named, 1);
}

}  // namespace
}  // namespace giocal
