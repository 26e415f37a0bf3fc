// examples/robot_driver.cc with --state: a robot's second drive resumes from the calibration its
// first drive saved, and a state file cut by a power failure starts the drive cold, not never.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "sim/simulator.h"
#include "temp_dir.h"

namespace giocal {
namespace {

struct Output {
  std::string text;
  int code = -1;
};

Output runExample(const std::string& args) {
  const std::string cmd = std::string(ROBOT_DRIVER_BINARY) + " " + args + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  Output r;
  char buf[512];
  while (p && std::fgets(buf, sizeof(buf), p)) r.text += buf;
  if (p) r.code = WEXITSTATUS(pclose(p));
  return r;
}

// The sigma of s_w the node printed at its first timer with a calibration.
double firstSigmaSw(const std::string& text) {
  std::smatch m;
  const std::regex re(R"(s_w [-+][0-9.]+ \(([0-9.]+)\))");
  if (!std::regex_search(text, m, re)) return NAN;
  return std::stod(m[1]);
}

TEST(RobotDriverExample, ASecondDriveResumesFromTheFirstsSavedCalibration) {
  test::TempDir dir;
  const sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml");
  sim::writeDataset(sim::simulate(cfg, 4511), dir.file("drive1"));
  sim::writeDataset(sim::simulate(cfg, 4512), dir.file("drive2"));
  const std::string state = dir.file("state.json");

  const Output cold = runExample(dir.file("drive2") + " ekf");
  ASSERT_EQ(cold.code, 0) << cold.text;
  const Output first = runExample(dir.file("drive1") + " ekf --state " + state);
  ASSERT_EQ(first.code, 0) << first.text;
  EXPECT_NE(first.text.find("cold start"), std::string::npos) << first.text;
  ASSERT_TRUE(std::filesystem::exists(state));

  const Output second = runExample(dir.file("drive2") + " ekf --state " + state);
  ASSERT_EQ(second.code, 0) << second.text;
  EXPECT_NE(second.text.find("resumed from " + state), std::string::npos) << second.text;
  // Drive 2 starts knowing what drive 1 learned: its first s_w sigma is far below the cold
  // start's (measured 0.0021 against 0.0200, the prior's sigma until the first turns).
  const double sd_cold = firstSigmaSw(cold.text), sd_warm = firstSigmaSw(second.text);
  std::printf("first s_w sigma: cold %.4f, resumed %.4f\n", sd_cold, sd_warm);
  EXPECT_LT(sd_warm, 0.5 * sd_cold);

  // A state file cut short (the power failed while it was written elsewhere): a cold start.
  std::string text;
  {
    std::ifstream in(state);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  std::ofstream(state) << text.substr(0, text.size() / 2);
  const Output cut = runExample(dir.file("drive2") + " ekf --state " + state);
  ASSERT_EQ(cut.code, 0) << cut.text;
  EXPECT_NE(cut.text.find("cold start"), std::string::npos) << cut.text;
  EXPECT_EQ(cut.text.find("resumed"), std::string::npos) << cut.text;
}

}  // namespace
}  // namespace giocal
