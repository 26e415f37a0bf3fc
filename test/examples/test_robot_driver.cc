// examples/robot_driver.cc with --state: a robot's second drive resumes from the calibration its
// first drive saved, and a state file cut by a power failure starts the drive cold, not never.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "../cli/run_giocal.h"
#include "sim/simulator.h"
#include "temp_dir.h"

namespace giocal {
namespace {

test::GiocalResult runExample(const std::string& args) {
  return test::runProgram(ROBOT_DRIVER_BINARY, args);
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

  const test::GiocalResult cold = runExample(dir.file("drive2") + " ekf");
  ASSERT_EQ(cold.code, 0) << cold.out;
  const test::GiocalResult first = runExample(dir.file("drive1") + " ekf --state " + state);
  ASSERT_EQ(first.code, 0) << first.out;
  EXPECT_NE(first.out.find("cold start"), std::string::npos) << first.out;
  ASSERT_TRUE(std::filesystem::exists(state));

  const test::GiocalResult second = runExample(dir.file("drive2") + " ekf --state " + state);
  ASSERT_EQ(second.code, 0) << second.out;
  EXPECT_NE(second.out.find("resumed from " + state), std::string::npos) << second.out;
  // Drive 2 starts knowing what drive 1 learned: its first s_w sigma is far below the cold
  // start's (measured 0.0021 against 0.0200, the prior's sigma until the first turns).
  const double sd_cold = firstSigmaSw(cold.out), sd_warm = firstSigmaSw(second.out);
  std::printf("first s_w sigma: cold %.4f, resumed %.4f\n", sd_cold, sd_warm);
  EXPECT_LT(sd_warm, 0.5 * sd_cold);

  // A state file cut short (the power failed while it was written elsewhere): a cold start.
  std::string text;
  {
    std::ifstream in(state);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  std::ofstream(state) << text.substr(0, text.size() / 2);
  const test::GiocalResult cut = runExample(dir.file("drive2") + " ekf --state " + state);
  ASSERT_EQ(cut.code, 0) << cut.out;
  EXPECT_NE(cut.out.find("cold start"), std::string::npos) << cut.out;
  EXPECT_EQ(cut.out.find("resumed"), std::string::npos) << cut.out;
}

}  // namespace
}  // namespace giocal
