// calibrate --state-out: the calibration a robot keeps across power cycles, written atomically
// with a checksum as the run goes and at its end; --prior reads it; a damaged one starts cold.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "field_laps.h"
#include "run_giocal.h"
#include "temp_dir.h"

extern char** environ;

namespace giocal {
namespace {

nlohmann::json jsonOf(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

TEST(StateFile, WrittenAsTheRunGoesReadBackAndADamagedOneStartsCold) {
  test::TempDir dir;
  const std::string preset = test::fieldPresetWithLaps(dir, 3);
  const std::string data = dir.file("d"), state = dir.file("state.json");
  ASSERT_EQ(test::runGiocal("simulate --config " + preset + " --seed 5301 --out " + data).code, 0);
  // A power cut (SIGKILL) part way through a factor-graph run: the state file is whole, older
  // than the end of the data by the time the run had left.
  {
    std::vector<std::string> args{
        GIOCAL_BINARY, "calibrate",        "--data",      data,  "--estimator",   "fgo", "--quiet",
        "--out",       dir.file("killed"), "--state-out", state, "--state-every", "20"};
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    pid_t pid = 0;
    ASSERT_EQ(posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ), 0);
    posix_spawn_file_actions_destroy(&actions);
    for (int i = 0; i < 6000 && !std::filesystem::exists(state); ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
  }
  ASSERT_TRUE(std::filesystem::exists(state));
  const nlohmann::json cut_short = jsonOf(state);
  EXPECT_TRUE(cut_short.contains("checksum"));
  // The whole run, its state written at the end: the final calibration of its summary.
  const test::GiocalResult full = test::runGiocal("calibrate --data " + data + " --quiet --out " +
                                                  dir.file("full") + " --state-out " + state);
  ASSERT_EQ(full.code, 0) << full.out;
  const nlohmann::json end = jsonOf(state), summary = jsonOf(dir.file("full") + "/summary.json");
  EXPECT_DOUBLE_EQ(end["t_final"].get<double>(), summary["t_final"].get<double>());
  EXPECT_DOUBLE_EQ(end["final"]["s_v"].get<double>(), summary["final"]["s_v"].get<double>());
  EXPECT_LT(cut_short["t_final"].get<double>(), end["t_final"].get<double>() - 60.0);
  EXPECT_FALSE(std::filesystem::exists(state + ".tmp"));
  // Read back as a prior.
  const test::GiocalResult warm = test::runGiocal("calibrate --data " + data + " --quiet --out " +
                                                  dir.file("warm") + " --prior " + state);
  EXPECT_EQ(warm.code, 0) << warm.out;
  EXPECT_NE(warm.out.find("started from " + state), std::string::npos) << warm.out;
  // Cut in half, or one digit changed: detected, and the run starts cold.
  std::string text;
  {
    std::ifstream in(state);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  std::ofstream(dir.file("cut.json")) << text.substr(0, text.size() / 2);
  std::string changed = text;
  changed[changed.find("\"s_v\": ") + 8] =
      changed[changed.find("\"s_v\": ") + 8] == '1' ? '2' : '1';
  std::ofstream(dir.file("changed.json")) << changed;
  // Another format: refused with one line, not taken for a damaged file.
  std::string other = text;
  other.replace(other.find("giocal state 1"), 14, "giocal state 9");
  std::ofstream(dir.file("other.json")) << other;
  const test::GiocalResult refused =
      test::runGiocal("calibrate --data " + data + " --quiet --out " + dir.file("other") +
                      " --prior " + dir.file("other.json"));
  EXPECT_EQ(refused.code, 1) << refused.out;
  EXPECT_NE(refused.out.find("a state file of another format"), std::string::npos) << refused.out;
  for (const char* damaged : {"cut.json", "changed.json"}) {
    const test::GiocalResult cold =
        test::runGiocal("calibrate --data " + data + " --quiet --out " + dir.file("cold") +
                        " --overwrite --prior " + dir.file(damaged));
    EXPECT_EQ(cold.code, 0) << cold.out;
    EXPECT_NE(cold.out.find("the run starts cold"), std::string::npos) << damaged << cold.out;
    EXPECT_EQ(cold.out.find("started from"), std::string::npos) << damaged;
  }
}

}  // namespace
}  // namespace giocal
